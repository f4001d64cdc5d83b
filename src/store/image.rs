//! The stored image: two slots (A and B) in the application's
//! non-volatile memory, each holding one complete, self-checking copy of
//! the stored parameters.
//!
//! Layout of a slot (all numbers little-endian, offsets from the slot
//! start; the slot is half of [`NvMemory::size`], rounded down to
//! [`SLOT_ALIGN`]):
//!
//! | offset | size | field |
//! |---|---|---|
//! | 0 | 4 | magic 0x5350_4F43 ("COPS") |
//! | 4 | 2 | format version ([`FORMAT_VERSION`]) |
//! | 6 | 2 | header length ([`HEADER_LEN`]) |
//! | 8 | 4 | sequence number (the newer slot has the larger one, modulo 2^32) |
//! | 12 | 4 | dictionary signature ([`Records::signature`]) |
//! | 16 | 4 | configuration key (`OD_BUILDER_KEY`) |
//! | 20 | 1 | parts present (`kObdPartGen` 0x01, `Man` 0x02, `Dev` 0x04) |
//! | 21 | 3 | reserved, 0 |
//! | 24 | 3 × 8 | per part Gen, Man, Dev: length of its block, CRC-32 of its block |
//! | 48 | 4 | CRC-32 of bytes 0..48 |
//!
//! The blocks follow at [`PAYLOAD_OFFSET`], one after the other in the
//! order Gen, Man, Dev. A block is a list of records
//! `index (2) | subindex (1) | length (1) | value (length bytes, CANopen
//! order)`.
//!
//! Writing a new image (`store`): the slot that does not hold the newest
//! valid image is erased, the blocks are written, the driver commits, and
//! only then the header, then a second commit. Until the header's last
//! byte is written the new slot fails its header CRC, so a power cut at any
//! moment leaves the old image (in the other slot) the newest valid one;
//! after it the new image is. Reading (`load`) checks both slots
//! completely (header CRC, version, signature, key, every block CRC and
//! every record against the dictionary) before one value is applied.
//!
//! No heap: the write-back goes through one buffer of [`CHUNK`] bytes and
//! one record of at most [`OBJECT_MAX`] value bytes, both on the stack.

use crc::{CRC_32_ISO_HDLC, Crc, NoTable};

/// "COPS" read as a little-endian UNSIGNED32.
pub const MAGIC: u32 = 0x5350_4F43;
/// Format version written and accepted.
pub const FORMAT_VERSION: u16 = 1;
/// Header length without its CRC.
pub const HEADER_LEN: usize = 48;
/// The blocks start here (header and CRC padded to it).
pub const PAYLOAD_OFFSET: u32 = 64;
/// Write buffer (build-time constant): the RAM of a write-back. The
/// driver's alignment must divide it.
pub const CHUNK: usize = 64;
/// Largest value stored (build-time constant). Wider objects (long
/// strings, domains) are not part of the image.
pub const OBJECT_MAX: usize = 64;
/// Slots start at multiples of this (flash sectors are usually larger:
/// a driver maps its sectors itself).
pub const SLOT_ALIGN: u32 = 64;
/// The parts an image holds, in block order (`kObdPartGen`, `Man`, `Dev`).
pub const PARTS: [u8; 3] = [0x01, 0x02, 0x04];

static CRC32: Crc<u32, NoTable> = Crc::<u32, NoTable>::new(&CRC_32_ISO_HDLC);

/// A driver call failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NvFault;

/// The non-volatile memory contract (the C side is `tCopStoreDriver`,
/// `include/target.h`). Offsets are from the start of the memory given to
/// the stack.
pub trait NvMemory {
    /// Usable bytes.
    fn size(&self) -> u32;
    /// Write granularity in bytes: a power of two dividing [`CHUNK`];
    /// every write starts at a multiple of it and is a multiple of it long.
    fn align(&self) -> u32;
    /// Reads `out.len()` bytes at `offset`.
    fn read(&mut self, offset: u32, out: &mut [u8]) -> Result<(), NvFault>;
    /// Writes `data` at `offset` (erased before).
    fn write(&mut self, offset: u32, data: &[u8]) -> Result<(), NvFault>;
    /// Erases `len` bytes at `offset` (a slot).
    fn erase(&mut self, offset: u32, len: u32) -> Result<(), NvFault>;
    /// Makes every write so far durable (flush a page buffer, sync a file).
    fn commit(&mut self) -> Result<(), NvFault>;
}

/// Why an image cannot be stored or loaded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageError {
    /// No driver, or a driver call failed.
    Driver,
    /// The driver's size or alignment cannot hold two slots of this format.
    Geometry,
    /// The parameters do not fit into a slot.
    Full,
    /// No slot holds a valid image (never stored, or both damaged).
    NoImage,
    /// The newest valid-looking image was written for another dictionary
    /// (other objects or sizes) or another configuration key; nothing of
    /// it is applied.
    Foreign,
    /// The image is intact but names an object the dictionary refuses
    /// (checked before anything is applied).
    Rejected,
}

/// A visitor of records: `(index, sub, value)`. A trait, not a `dyn`
/// type, so that every visit is a direct call (the worst-case stack
/// analysis of docs/tms570.md follows direct calls exactly).
pub trait Visit: FnMut(u16, u8, &[u8]) -> Result<(), ImageError> {}

impl<F: FnMut(u16, u8, &[u8]) -> Result<(), ImageError> + ?Sized> Visit for F {}

/// What the stack offers the image: the stored objects of each part.
pub trait Records {
    /// Signature of the dictionary layout (objects, subindices, sizes).
    fn signature(&self) -> u32;
    /// Calls `f(index, sub, value)` for every stored object of `part`.
    fn each<F: Visit + ?Sized>(&self, part: u8, f: &mut F) -> Result<(), ImageError>;
    /// Whether `value` would be accepted for `(index, sub)` (no change).
    fn check(&self, index: u16, sub: u8, value: &[u8]) -> bool;
    /// Applies a checked value.
    fn apply(&mut self, index: u16, sub: u8, value: &[u8]) -> Result<(), ImageError>;
}

/// A valid slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SlotInfo {
    /// 0 = A, 1 = B.
    pub slot: u8,
    /// Sequence number.
    pub seq: u32,
    /// Parts present.
    pub parts: u8,
    blocks: [(u32, u32); 3],
}

/// Geometry of a memory: slot length, alignment.
fn geometry<N: NvMemory + ?Sized>(nv: &N) -> Result<(u32, u32), ImageError> {
    let align = nv.align();
    if align == 0 || !align.is_power_of_two() || align as usize > CHUNK {
        return Err(ImageError::Geometry);
    }
    let slot = (nv.size() / 2) / SLOT_ALIGN * SLOT_ALIGN;
    if slot <= PAYLOAD_OFFSET {
        return Err(ImageError::Geometry);
    }
    Ok((slot, align))
}

fn le16(b: &[u8], at: usize) -> u16 {
    let mut v = [0u8; 2];
    if let Some(s) = b.get(at..at + 2) {
        v.copy_from_slice(s);
    }
    u16::from_le_bytes(v)
}

fn le32(b: &[u8], at: usize) -> u32 {
    let mut v = [0u8; 4];
    if let Some(s) = b.get(at..at + 4) {
        v.copy_from_slice(s);
    }
    u32::from_le_bytes(v)
}

fn put(b: &mut [u8], at: usize, v: &[u8]) {
    if let Some(d) = b.get_mut(at..at + v.len()) {
        d.copy_from_slice(v);
    }
}

/// Sequence `a` newer than `b` (modulo 2^32).
fn newer(a: u32, b: u32) -> bool {
    (a.wrapping_sub(b) as i32) > 0
}

/// Reads and checks the header of `slot`; `None` when it is not a valid
/// header of this format. `Some(Err(Foreign))` for another dictionary.
// Out of line: its buffer is on the stack only while it runs, not under
// the calls its caller makes (worst-case stack, docs/tms570.md).
#[inline(never)]
fn header<N: NvMemory + ?Sized>(
    nv: &mut N,
    slot: u8,
    slot_len: u32,
    signature: u32,
    key: u32,
) -> Option<Result<SlotInfo, ImageError>> {
    let mut h = [0u8; HEADER_LEN + 4];
    nv.read(u32::from(slot) * slot_len, &mut h).ok()?;
    let body = h.get(..HEADER_LEN)?;
    if le32(&h, 0) != MAGIC || CRC32.checksum(body) != le32(&h, HEADER_LEN) {
        return None;
    }
    if le16(&h, 4) != FORMAT_VERSION || usize::from(le16(&h, 6)) != HEADER_LEN {
        return Some(Err(ImageError::Foreign));
    }
    if le32(&h, 12) != signature || le32(&h, 16) != key {
        return Some(Err(ImageError::Foreign));
    }
    let mut blocks = [(0u32, 0u32); 3];
    for (i, b) in blocks.iter_mut().enumerate() {
        *b = (le32(&h, 24 + 8 * i), le32(&h, 28 + 8 * i));
    }
    let total = blocks.iter().fold(0u64, |a, b| a + u64::from(b.0));
    if total > u64::from(slot_len - PAYLOAD_OFFSET) {
        return None;
    }
    let parts = h.get(20).copied().unwrap_or(0);
    Some(Ok(SlotInfo {
        slot,
        seq: le32(&h, 8),
        parts,
        blocks,
    }))
}

/// The sequence number of a slot whose header is intact (any
/// dictionary), `None` for an empty or damaged slot.
// Out of line: its buffer is on the stack only while it runs, not under
// the calls its caller makes (worst-case stack, docs/tms570.md).
#[inline(never)]
fn occupied<N: NvMemory + ?Sized>(nv: &mut N, slot: u8, slot_len: u32) -> Option<u32> {
    let mut h = [0u8; HEADER_LEN + 4];
    nv.read(u32::from(slot) * slot_len, &mut h).ok()?;
    let body = h.get(..HEADER_LEN)?;
    (le32(&h, 0) == MAGIC && CRC32.checksum(body) == le32(&h, HEADER_LEN)).then(|| le32(&h, 8))
}

/// Walks the records of one block; `f` sees each.
// Out of line: its buffer is on the stack only while it runs, not under
// the calls its caller makes (worst-case stack, docs/tms570.md).
#[inline(never)]
fn walk<N: NvMemory + ?Sized, F: Visit + ?Sized>(
    nv: &mut N,
    mut at: u32,
    len: u32,
    crc_expected: u32,
    f: &mut F,
) -> Result<(), ImageError> {
    let end = at + len;
    let mut digest = CRC32.digest();
    let mut rec = [0u8; 4 + OBJECT_MAX];
    let mut refused = Ok(());
    while at < end {
        let head = rec.get_mut(..4).ok_or(ImageError::NoImage)?;
        if end - at < 4 {
            return Err(ImageError::NoImage);
        }
        nv.read(at, head).map_err(|_| ImageError::Driver)?;
        let n = usize::from(head.get(3).copied().unwrap_or(0));
        if n > OBJECT_MAX || u64::from(end - at) < 4 + n as u64 {
            return Err(ImageError::NoImage);
        }
        let whole = rec.get_mut(..4 + n).ok_or(ImageError::NoImage)?;
        nv.read(at + 4, whole.get_mut(4..).unwrap_or(&mut []))
            .map_err(|_| ImageError::Driver)?;
        digest.update(whole);
        let value = whole.get(4..).unwrap_or(&[]);
        if refused.is_ok() {
            refused = f(le16(whole, 0), whole.get(2).copied().unwrap_or(0), value);
        }
        at += 4 + n as u32;
    }
    // A damaged block is reported as such, before what `f` said of it.
    if digest.finalize() != crc_expected {
        return Err(ImageError::NoImage);
    }
    refused
}

fn payload_start(info: &SlotInfo, slot_len: u32, block: usize) -> u32 {
    let before: u32 = info.blocks.iter().take(block).map(|b| b.0).sum();
    u32::from(info.slot) * slot_len + PAYLOAD_OFFSET + before
}

/// Checks one slot completely: its header and every block CRC, and that
/// every record is accepted by `records` (nothing applied).
fn verify<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &R,
    slot: u8,
    slot_len: u32,
    key: u32,
) -> Result<SlotInfo, ImageError> {
    let info =
        header(nv, slot, slot_len, records.signature(), key).ok_or(ImageError::NoImage)??;
    for (i, &(len, crc)) in info.blocks.iter().enumerate() {
        let at = payload_start(&info, slot_len, i);
        walk(nv, at, len, crc, &mut |index, sub, v| {
            if records.check(index, sub, v) {
                Ok(())
            } else {
                Err(ImageError::Rejected)
            }
        })?;
    }
    Ok(info)
}

/// The newest slot that passes `verify`; the error of the newest
/// candidate when none passes (Foreign before NoImage).
pub fn newest<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &R,
    key: u32,
) -> Result<SlotInfo, ImageError> {
    let (slot_len, _) = geometry(nv)?;
    let a = verify(nv, records, 0, slot_len, key);
    let b = verify(nv, records, 1, slot_len, key);
    match (a, b) {
        (Ok(a), Ok(b)) => Ok(if newer(b.seq, a.seq) { b } else { a }),
        (Ok(a), Err(_)) => Ok(a),
        (Err(_), Ok(b)) => Ok(b),
        (Err(e), Err(f)) => Err(worst(e, f)),
    }
}

/// Reports the most telling of two failures.
fn worst(a: ImageError, b: ImageError) -> ImageError {
    let rank = |e: ImageError| match e {
        ImageError::Driver => 5,
        ImageError::Geometry => 4,
        ImageError::Foreign => 3,
        ImageError::Rejected => 2,
        ImageError::Full => 1,
        ImageError::NoImage => 0,
    };
    if rank(a) >= rank(b) { a } else { b }
}

/// Applies the parts `parts` of the newest valid image: checked entirely
/// first, then applied. Returns the parts applied (those both asked for
/// and present).
pub fn load<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &mut R,
    key: u32,
    parts: u8,
) -> Result<u8, ImageError> {
    let info = newest(nv, records, key)?;
    let (slot_len, _) = geometry(nv)?;
    for (i, &(len, crc)) in info.blocks.iter().enumerate() {
        let part = PARTS.get(i).copied().unwrap_or(0);
        if part & parts & info.parts == 0 {
            continue;
        }
        let at = payload_start(&info, slot_len, i);
        walk(nv, at, len, crc, &mut |index, sub, v| {
            records.apply(index, sub, v)
        })?;
    }
    Ok(info.parts & parts)
}

/// Whether a valid image holds every part of `parts`.
pub fn holds<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &R,
    key: u32,
    parts: u8,
) -> Result<(), ImageError> {
    let info = newest(nv, records, key)?;
    if info.parts & parts == parts {
        Ok(())
    } else {
        Err(ImageError::NoImage)
    }
}

/// Streams bytes into the memory through [`CHUNK`] bytes, aligned.
struct Writer<'a, N: NvMemory + ?Sized> {
    nv: &'a mut N,
    at: u32,
    end: u32,
    buf: [u8; CHUNK],
    fill: usize,
    align: usize,
}

impl<N: NvMemory + ?Sized> Writer<'_, N> {
    fn push(&mut self, mut data: &[u8]) -> Result<(), ImageError> {
        while !data.is_empty() {
            let room = CHUNK - self.fill;
            let n = room.min(data.len());
            let (head, rest) = data.split_at(n);
            put(&mut self.buf, self.fill, head);
            self.fill += n;
            data = rest;
            if self.fill == CHUNK {
                self.flush()?;
            }
        }
        Ok(())
    }

    fn flush(&mut self) -> Result<(), ImageError> {
        if self.fill == 0 {
            return Ok(());
        }
        let len = self.fill.div_ceil(self.align) * self.align;
        for b in self.buf.get_mut(self.fill..len).unwrap_or(&mut []) {
            *b = 0xFF;
        }
        if u64::from(self.at) + len as u64 > u64::from(self.end) {
            return Err(ImageError::Full);
        }
        let chunk = self.buf.get(..len).ok_or(ImageError::Full)?;
        self.nv
            .write(self.at, chunk)
            .map_err(|_| ImageError::Driver)?;
        self.at += len as u32;
        self.fill = 0;
        Ok(())
    }
}

/// Stores `parts` from `records` into a new image, leaving out the parts
/// of `drop` and keeping the other parts of the newest valid image (when
/// it belongs to this dictionary).
/// Returns the slot written. A failure at any point leaves the previous
/// image the newest valid one.
pub fn store<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &R,
    key: u32,
    parts: u8,
    drop: u8,
) -> Result<SlotInfo, ImageError> {
    let (slot_len, align) = geometry(nv)?;
    let old = newest(nv, records, key).ok();
    // Never overwrite the newest intact slot, even one of another
    // dictionary: a refused store must leave it as it was.
    let target: u8 = match (old, occupied(nv, 0, slot_len), occupied(nv, 1, slot_len)) {
        (Some(o), _, _) => 1 - o.slot.min(1),
        (None, Some(a), Some(b)) => u8::from(newer(b, a)),
        (None, Some(_), None) => 1,
        (None, _, _) => 0,
    };
    write_slot(nv, records, key, parts, drop, old, target, slot_len, align)
}

/// [`store`] after the choice of the slot: writes `target`. Out of line,
/// so that its buffers are not on the stack while [`store`] checks the old
/// image (worst-case stack, docs/tms570.md).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn write_slot<N: NvMemory + ?Sized, R: Records + ?Sized>(
    nv: &mut N,
    records: &R,
    key: u32,
    parts: u8,
    drop: u8,
    old: Option<SlotInfo>,
    target: u8,
    slot_len: u32,
    align: u32,
) -> Result<SlotInfo, ImageError> {
    let base = u32::from(target) * slot_len;
    nv.erase(base, slot_len).map_err(|_| ImageError::Driver)?;
    let mut w = Writer {
        nv,
        at: base + PAYLOAD_OFFSET,
        end: base + slot_len,
        buf: [0; CHUNK],
        fill: 0,
        align: align as usize,
    };
    let mut blocks = [(0u32, 0u32); 3];
    let mut present = 0u8;
    for (i, &part) in PARTS.iter().enumerate() {
        let mut len = 0u32;
        let mut digest = CRC32.digest();
        let mut kept = None;
        if part & parts != 0 {
            records.each(part, &mut |index, sub, v| {
                let n = u8::try_from(v.len()).map_err(|_| ImageError::Full)?;
                let mut head = [0u8; 4];
                put(&mut head, 0, &index.to_le_bytes());
                put(&mut head, 2, &[sub, n]);
                digest.update(&head);
                digest.update(v);
                w.push(&head)?;
                w.push(v)?;
                len += 4 + u32::from(n);
                Ok(())
            })?;
            present |= part;
        } else if let Some(o) = old.filter(|o| o.parts & part != 0 && drop & part == 0) {
            // Keep the stored part: copy its block from the old slot.
            let (olen, ocrc) = o.blocks.get(i).copied().unwrap_or((0, 0));
            let mut at = payload_start(&o, slot_len, i);
            let end = at + olen;
            let mut tmp = [0u8; CHUNK];
            while at < end {
                let n = (end - at).min(CHUNK as u32);
                let t = tmp.get_mut(..n as usize).ok_or(ImageError::Full)?;
                w.nv.read(at, t).map_err(|_| ImageError::Driver)?;
                digest.update(t);
                w.push(t)?;
                at += n;
            }
            len = olen;
            kept = Some(ocrc);
            present |= part;
        }
        let crc = digest.finalize();
        if kept.is_some_and(|k| k != crc) {
            // The old block changed under us: do not carry it over.
            return Err(ImageError::NoImage);
        }
        if let Some(b) = blocks.get_mut(i) {
            *b = (len, crc);
        }
    }
    w.flush()?;
    w.nv.commit().map_err(|_| ImageError::Driver)?;
    let seq = old.map_or(1, |o| o.seq.wrapping_add(1));
    let mut h = [0u8; PAYLOAD_OFFSET as usize];
    put(&mut h, 0, &MAGIC.to_le_bytes());
    put(&mut h, 4, &FORMAT_VERSION.to_le_bytes());
    put(&mut h, 6, &(HEADER_LEN as u16).to_le_bytes());
    put(&mut h, 8, &seq.to_le_bytes());
    put(&mut h, 12, &records.signature().to_le_bytes());
    put(&mut h, 16, &key.to_le_bytes());
    put(&mut h, 20, &[present]);
    for (i, (len, crc)) in blocks.iter().enumerate() {
        put(&mut h, 24 + 8 * i, &len.to_le_bytes());
        put(&mut h, 28 + 8 * i, &crc.to_le_bytes());
    }
    let crc = CRC32.checksum(h.get(..HEADER_LEN).unwrap_or(&[]));
    put(&mut h, HEADER_LEN, &crc.to_le_bytes());
    for b in h.get_mut(HEADER_LEN + 4..).unwrap_or(&mut []) {
        *b = 0xFF;
    }
    w.nv.write(base, &h).map_err(|_| ImageError::Driver)?;
    w.nv.commit().map_err(|_| ImageError::Driver)?;
    Ok(SlotInfo {
        slot: target,
        seq,
        parts: present,
        blocks,
    })
}

/// Invalidates both slots (`CcmStoreRestoreDefault`): the next start uses
/// the defaults.
pub fn erase_all<N: NvMemory + ?Sized>(nv: &mut N) -> Result<(), ImageError> {
    let (slot_len, _) = geometry(nv)?;
    nv.erase(0, slot_len).map_err(|_| ImageError::Driver)?;
    nv.erase(slot_len, slot_len)
        .map_err(|_| ImageError::Driver)?;
    nv.commit().map_err(|_| ImageError::Driver)
}

/// Signature helper: CRC-32 over `(index, sub, length, type code)` of
/// every stored object, fed by the caller.
pub struct SignatureDigest(crc::Digest<'static, u32, NoTable>);

impl SignatureDigest {
    /// Empty.
    pub fn new() -> Self {
        SignatureDigest(CRC32.digest())
    }
    /// One object.
    pub fn object(&mut self, index: u16, sub: u8, len: usize, type_code: u8) {
        let l = u16::try_from(len).unwrap_or(u16::MAX);
        self.0.update(&index.to_le_bytes());
        self.0.update(&[sub, type_code]);
        self.0.update(&l.to_le_bytes());
    }
    /// The signature.
    pub fn finish(self) -> u32 {
        self.0.finalize()
    }
}

crate::od::decl::default_is_new!(SignatureDigest);

#[cfg(test)]
#[path = "image_tests.rs"]
mod tests;
