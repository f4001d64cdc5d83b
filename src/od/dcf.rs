//! The binary DCF container of the dynamic object dictionary (SYS TEC
//! CcmDyn, seed manual L-1087d chapter 2): parsing, validation and encoding.
//! Pure byte work, no dictionary and no state.
//!
//! # Layout (every multi-byte value little-endian, whatever the CPU)
//! ```text
//! header (40 bytes)      DWORD total size, WORD version (1), WORD number of
//!                        segments (not used: real containers carry 0), then
//!                        offset/size DWORD pairs of the four segments below
//! index segment          CiA 302 concise DCF: DWORD count, then per entry
//!                        WORD index, BYTE subindex, DWORD size, data
//! PI address segment     optional: one WORD per process-image candidate
//!                        (see [`is_pi_candidate`]), 0xFFFF = not placed
//! extended info segment  one attribute BYTE per index-segment entry
//! PI parameter segment   optional: five DWORDs (see [`PiParams`])
//! ```
//!
//! # What [`Container::parse`] refuses
//! A container is taken only when every byte is accounted for: the size
//! field is at least the header and not more than the bytes given, the
//! version is 1, every segment lies inside the container after the header,
//! an unused segment has offset and size 0, the segments do not overlap
//! and their sizes plus the header add up to the total size (so there are
//! no gaps either), the index segment holds exactly the number of entries
//! its count names and nothing after them, the extended info segment has
//! one byte per entry, no attribute uses the reserved bits 0x02/0x04 or
//! names two data types, a BOOLEAN entry has one byte and a numeric one
//! 1..=8 bytes, the address segment has one WORD per candidate and the
//! parameter segment five DWORDs whose windows lie inside the image.
//!
//! # The index of the entries
//! Entries of one object may come in any order and more than once, so
//! questions like "the last entry of 0x1A00 sub 1", "the subindices of
//! 0x2100 in ascending order" or "does 0xA4C0 have other subindices than
//! 0" need a pass over the container each. [`Container::parse_indexed`]
//! answers them from an index built once in scratch memory the caller
//! lends (no heap; [`index_scratch_len`] bytes): the entries sorted by
//! index, subindex and position (a stable merge sort, O(n log n), one
//! comparison per entry for a sorted container), plus a few flags per
//! entry. Every answer is the one of the scanning container; the build of
//! the dynamic OD is linear in the entries (up to the sort) with it and
//! quadratic without.

use super::DataType;
use crate::error::CopKernel;

mod index;
use index::Index;

/// Size of the header segment.
pub const HEADER_SIZE: usize = 40;
/// The only container version this library knows.
pub const VERSION: u16 = 1;
/// Size of the process-image parameter segment (five DWORDs).
pub const PI_PARAM_SIZE: usize = 20;
/// Address word of a process-image candidate that is not placed.
pub const NOT_PLACED: u16 = 0xFFFF;
/// Bytes before the data of one index-segment entry.
pub const ENTRY_HEADER_SIZE: usize = 7;

/// Attribute bits of the extended info segment (seed table 1).
pub mod attr {
    /// The entry is a BOOLEAN.
    pub const BOOLEAN: u8 = 0x01;
    /// Reserved bits: a container using them is refused.
    pub const RESERVED: u8 = 0x06;
    /// The entry is a VISIBLE_STRING (copied byte by byte).
    pub const VISIBLE_STRING: u8 = 0x08;
    /// The entry is a number, stored in the CPU's byte order.
    pub const NUMERIC: u8 = 0x10;
    /// Reading is allowed.
    pub const READ: u8 = 0x20;
    /// Writing is allowed.
    pub const WRITE: u8 = 0x40;
    /// The entry may be mapped into a PDO.
    pub const PDO_MAPP: u8 = 0x80;
    /// The three type bits; none of them means DOMAIN.
    pub const TYPE_MASK: u8 = BOOLEAN | VISIBLE_STRING | NUMERIC;
    /// What 0xA000–0xAFFF objects always get (seed 2.1.2).
    pub const NETWORK_VARIABLE: u8 = NUMERIC | READ | WRITE | PDO_MAPP;
}

/// Which part of the container is wrong. Every variant is
/// `kCopDynInvalidConfig` for the C API; the variant and its numbers are
/// for diagnostics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContainerError {
    /// Fewer bytes than the header or than the total size names.
    Truncated,
    /// The total size field is smaller than the header.
    TotalSize,
    /// A version other than [`VERSION`].
    Version(u16),
    /// A segment lies (partly) outside the container or inside the header,
    /// or has an offset without size (or a size without offset).
    Segment(SegmentId),
    /// Two segments share bytes.
    Overlap(SegmentId, SegmentId),
    /// Header plus segment sizes differ from the total size.
    SizeMismatch,
    /// The index segment is missing or shorter than its count.
    IndexSegment,
    /// Bytes left in the index segment after the last entry.
    TrailingBytes,
    /// The extended info segment does not have one byte per entry.
    AttributeCount,
    /// Entry `entry` (counted from 0) has an attribute with reserved bits,
    /// two type bits, or a size its type cannot have.
    Attribute {
        /// Position of the entry.
        entry: u32,
        /// The attribute byte.
        value: u8,
    },
    /// The address segment size is odd or does not match the candidates.
    AddressCount,
    /// The parameter segment is not five DWORDs or names windows outside
    /// the image.
    PiParams,
}

impl ContainerError {
    /// The C API code: `kCopDynInvalidConfig`.
    pub const fn kernel(self) -> CopKernel {
        CopKernel::DynInvalidConfig
    }
}

/// The four segments after the header.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentId {
    /// Index segment (concise DCF).
    Index,
    /// Process-image address segment.
    Address,
    /// Extended info segment (attributes).
    ExtInfo,
    /// Process-image parameter segment.
    PiParam,
}

/// Offset and size of one segment (0/0 when absent).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Segment {
    /// Offset from the start of the container.
    pub offset: u32,
    /// Size in bytes.
    pub size: u32,
}

impl Segment {
    /// True when the segment is present.
    pub const fn present(&self) -> bool {
        self.size != 0
    }

    fn range(&self) -> Option<core::ops::Range<usize>> {
        let start = usize::try_from(self.offset).ok()?;
        let end = start.checked_add(usize::try_from(self.size).ok()?)?;
        Some(start..end)
    }
}

/// The header segment (seed Bild 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    /// Size of the whole container.
    pub total: u32,
    /// Format version.
    pub version: u16,
    /// Number of segments as written (not relied upon).
    pub segments: u16,
    /// Index segment.
    pub index: Segment,
    /// Process-image address segment.
    pub address: Segment,
    /// Extended info segment.
    pub ext_info: Segment,
    /// Process-image parameter segment.
    pub pi_param: Segment,
}

/// The process-image parameter segment (seed Bild 7), also what
/// `DynBuildOd` reports in `tProcessImageDscrpt`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PiParams {
    /// Complete size of the process image.
    pub total: u32,
    /// Offset of the input area.
    pub input_offset: u32,
    /// Size of the input area.
    pub input_size: u32,
    /// Offset of the output area.
    pub output_offset: u32,
    /// Size of the output area.
    pub output_size: u32,
}

impl PiParams {
    /// True when `len` bytes at `at` lie within the image's size and
    /// entirely inside the input or the output area.
    pub fn covers(&self, at: u32, len: usize) -> bool {
        let Ok(len) = u32::try_from(len) else {
            return false;
        };
        let Some(end) = at.checked_add(len) else {
            return false;
        };
        let inside = |o: u32, s: u32| at >= o && o.checked_add(s).is_some_and(|e| end <= e);
        end <= self.total
            && (inside(self.input_offset, self.input_size)
                || inside(self.output_offset, self.output_size))
    }

    fn consistent(&self) -> bool {
        let fits = |o: u32, s: u32| o.checked_add(s).is_some_and(|end| end <= self.total);
        fits(self.input_offset, self.input_size) && fits(self.output_offset, self.output_size)
    }

    /// The five DWORDs little-endian.
    pub fn to_bytes(&self) -> [u8; PI_PARAM_SIZE] {
        let mut out = [0u8; PI_PARAM_SIZE];
        let words = [
            self.total,
            self.input_offset,
            self.input_size,
            self.output_offset,
            self.output_size,
        ];
        for (chunk, w) in out.chunks_exact_mut(4).zip(words) {
            chunk.copy_from_slice(&w.to_le_bytes());
        }
        out
    }
}

/// One index-segment entry with its attribute.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry<'a> {
    /// Position in the index segment, from 0.
    pub position: u32,
    /// Index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
    /// The value as stored in the container (CANopen byte order).
    pub data: &'a [u8],
    /// Attribute byte; `None` without extended info segment.
    pub attr: Option<u8>,
}

/// A validated container.
///
/// Questions about the entries (first and last occurrence of a subindex,
/// the subindices of an object, ...) scan the container, O(n) each, unless
/// the container was parsed with [`Container::parse_indexed`], which
/// builds an index of the entries in scratch memory: then they cost O(1)
/// or O(log n), those about all subindices of an object the number of its
/// entries. The answers are the same either way.
#[derive(Clone, Copy, Debug)]
pub struct Container<'a> {
    bytes: &'a [u8],
    header: Header,
    count: u32,
    /// The index segment.
    entry_bytes: &'a [u8],
    /// The extended info segment.
    attrs: Option<&'a [u8]>,
    index: Option<Index<'a>>,
}

/// What a container holds for one index ([`Container::subindices`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Subindices {
    /// Number of different subindices.
    pub distinct: usize,
    /// True when subindex 0 is among them.
    pub has_zero: bool,
    /// The highest subindex (0 when there is none).
    pub highest: u8,
}

impl Subindices {
    /// Counts the key `k` of a sorted index (index << 8 | subindex) unless
    /// it repeats the one before (`prev`).
    fn count_key(&mut self, prev: &mut Option<u32>, k: u32) {
        if *prev != Some(k) {
            let sub = k as u8;
            self.distinct += 1;
            self.has_zero |= sub == 0;
            self.highest = self.highest.max(sub);
            *prev = Some(k);
        }
    }

    /// True when the object has subindices, but not subindex 0 (an array or
    /// record whose count the container does not carry).
    pub const fn lacks_count(&self) -> bool {
        self.distinct > 0 && !self.has_zero
    }
}

fn le16(b: &[u8], at: usize) -> Option<u16> {
    let s = b.get(at..at.checked_add(2)?)?;
    Some(u16::from_le_bytes([*s.first()?, *s.get(1)?]))
}

fn le32(b: &[u8], at: usize) -> Option<u32> {
    let s = b.get(at..at.checked_add(4)?)?;
    let mut w = [0u8; 4];
    w.copy_from_slice(s);
    Some(u32::from_le_bytes(w))
}

/// Reads the total size field of a container: how many bytes the caller
/// must make available. `None` for fewer than four bytes.
pub fn declared_size(bytes: &[u8]) -> Option<u32> {
    le32(bytes, 0)
}

/// Scratch bytes [`Container::parse_indexed`] needs for an index of
/// `entries` entries in an index segment of `index_segment_len` bytes,
/// with or without address segment: 8 bytes per entry (10 with address
/// segment) for index segments below 64 KiB, 12 (14) from there on.
/// `None` on overflow.
pub fn index_scratch_len(
    entries: usize,
    index_segment_len: usize,
    address_segment: bool,
) -> Option<usize> {
    index::scratch_len(entries, index_segment_len, address_segment)
}

/// True when an entry is a process-image candidate, i.e. owns a WORD of
/// the address segment: an object from 0x2000 on, and either a subindex
/// from 1 on or subindex 0 of an object that has no other subindex in the
/// container (a simple variable). Communication objects and the count of
/// arrays and records are never placed.
pub const fn is_pi_candidate(index: u16, sub: u8, index_has_other_subs: bool) -> bool {
    index >= 0x2000 && (sub >= 1 || !index_has_other_subs)
}

impl<'a> Container<'a> {
    /// Parses and validates a container (see the module documentation for
    /// every rule). Bytes after the total size are ignored.
    pub fn parse(bytes: &'a [u8]) -> Result<Container<'a>, ContainerError> {
        let c = Self::parse_entries(bytes)?;
        c.check_optional_segments()?;
        Ok(c)
    }

    /// [`Container::parse`], and an index of the entries built at the end
    /// of `scratch` (see [`index_scratch_len`] for its size; the bytes
    /// before it are not touched). Same rules, same errors; when `scratch`
    /// is too small the container simply has no index.
    /// [`Container::index_len`] tells how many bytes the index took.
    pub fn parse_indexed(
        bytes: &'a [u8],
        scratch: &'a mut [u8],
    ) -> Result<Container<'a>, ContainerError> {
        let c = Self::parse_entries(bytes)?;
        let c = Container {
            index: Index::build(&c, scratch),
            ..c
        };
        c.check_optional_segments()?;
        Ok(c)
    }

    /// Bytes the index occupies at the end of the scratch given to
    /// [`Container::parse_indexed`] (0 without index).
    pub fn index_len(&self) -> usize {
        self.index.map_or(0, |ix| ix.len())
    }

    /// True when the container has an index of its entries.
    pub fn is_indexed(&self) -> bool {
        self.index.is_some()
    }

    /// The same container without its index (for when the scratch is
    /// about to be reused).
    pub fn without_index(self) -> Container<'a> {
        Container {
            index: None,
            ..self
        }
    }

    /// Everything [`Container::parse`] checks up to the attributes.
    fn parse_entries(bytes: &'a [u8]) -> Result<Container<'a>, ContainerError> {
        if bytes.len() < HEADER_SIZE {
            return Err(ContainerError::Truncated);
        }
        let word = |at| le32(bytes, at).ok_or(ContainerError::Truncated);
        let total = word(0)?;
        let total_len = usize::try_from(total).map_err(|_| ContainerError::Truncated)?;
        if total_len < HEADER_SIZE {
            return Err(ContainerError::TotalSize);
        }
        if total_len > bytes.len() {
            return Err(ContainerError::Truncated);
        }
        let bytes = bytes.get(..total_len).ok_or(ContainerError::Truncated)?;
        let version = le16(bytes, 4).ok_or(ContainerError::Truncated)?;
        if version != VERSION {
            return Err(ContainerError::Version(version));
        }
        let segments = le16(bytes, 6).ok_or(ContainerError::Truncated)?;
        let seg = |at: usize| -> Result<Segment, ContainerError> {
            Ok(Segment {
                offset: word(at)?,
                size: word(at + 4)?,
            })
        };
        let header = Header {
            total,
            version,
            segments,
            index: seg(8)?,
            address: seg(16)?,
            ext_info: seg(24)?,
            pi_param: seg(32)?,
        };
        let all = [
            (SegmentId::Index, header.index),
            (SegmentId::Address, header.address),
            (SegmentId::ExtInfo, header.ext_info),
            (SegmentId::PiParam, header.pi_param),
        ];
        let mut sum = HEADER_SIZE as u64;
        for (id, s) in all {
            if (s.offset == 0) != (s.size == 0) {
                return Err(ContainerError::Segment(id));
            }
            if !s.present() {
                continue;
            }
            let r = s.range().ok_or(ContainerError::Segment(id))?;
            if r.start < HEADER_SIZE || r.end > total_len {
                return Err(ContainerError::Segment(id));
            }
            sum += u64::from(s.size);
        }
        for (i, (a_id, a)) in all.iter().enumerate() {
            for (b_id, b) in all.iter().skip(i + 1) {
                if !a.present() || !b.present() {
                    continue;
                }
                let (ra, rb) = match (a.range(), b.range()) {
                    (Some(ra), Some(rb)) => (ra, rb),
                    _ => return Err(ContainerError::Segment(*a_id)),
                };
                if ra.start < rb.end && rb.start < ra.end {
                    return Err(ContainerError::Overlap(*a_id, *b_id));
                }
            }
        }
        if sum != u64::from(total) {
            return Err(ContainerError::SizeMismatch);
        }
        if header.index.size < 4 {
            return Err(ContainerError::IndexSegment);
        }
        let c = Container {
            bytes,
            header,
            count: 0,
            entry_bytes: &[],
            attrs: None,
            index: None,
        };
        let index = c
            .segment(header.index)
            .ok_or(ContainerError::IndexSegment)?;
        let count = le32(index, 0).ok_or(ContainerError::IndexSegment)?;
        // The attributes, when there is one per entry (else the count check
        // below refuses the container).
        let attrs = c
            .segment(header.ext_info)
            .filter(|a| a.len() as u64 == u64::from(count));
        let mut bad_attr = None;
        // Walk the entries once: each must be complete and the last one
        // must end exactly at the end of the segment. The first attribute
        // that does not fit its entry is reported after the checks of the
        // segments.
        let mut rest = index.get(4..).ok_or(ContainerError::IndexSegment)?;
        for position in 0..count {
            let (head, tail) = rest
                .split_first_chunk::<ENTRY_HEADER_SIZE>()
                .ok_or(ContainerError::IndexSegment)?;
            let [_, _, _, s0, s1, s2, s3] = *head;
            let size = usize::try_from(u32::from_le_bytes([s0, s1, s2, s3]))
                .map_err(|_| ContainerError::IndexSegment)?;
            if bad_attr.is_none() {
                if let Some(&a) = attrs.and_then(|a| a.get(position as usize)) {
                    if !attribute_fits(a, size) {
                        bad_attr = Some(ContainerError::Attribute {
                            entry: position,
                            value: a,
                        });
                    }
                }
            }
            rest = tail.get(size..).ok_or(ContainerError::IndexSegment)?;
        }
        if !rest.is_empty() {
            return Err(ContainerError::TrailingBytes);
        }
        let c = Container {
            count,
            entry_bytes: index,
            attrs: c.segment(header.ext_info),
            ..c
        };
        if header.ext_info.present() && u64::from(header.ext_info.size) != u64::from(count) {
            return Err(ContainerError::AttributeCount);
        }
        if let Some(err) = bad_attr {
            return Err(err);
        }
        Ok(c)
    }

    /// The checks of [`Container::parse`] after the attributes: the address
    /// and the parameter segment.
    fn check_optional_segments(&self) -> Result<(), ContainerError> {
        let header = &self.header;
        if header.address.present() {
            if header.address.size % 2 != 0 {
                return Err(ContainerError::AddressCount);
            }
            if u64::from(header.address.size / 2) != self.candidate_count() as u64 {
                return Err(ContainerError::AddressCount);
            }
        }
        if header.pi_param.present() {
            if header.pi_param.size as usize != PI_PARAM_SIZE {
                return Err(ContainerError::PiParams);
            }
            if !self.pi_params().is_some_and(|p| p.consistent()) {
                return Err(ContainerError::PiParams);
            }
        }
        Ok(())
    }

    fn segment(&self, s: Segment) -> Option<&'a [u8]> {
        if !s.present() {
            return None;
        }
        self.bytes.get(s.range()?)
    }

    /// The header.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The container's bytes (exactly its total size).
    pub fn bytes(&self) -> &'a [u8] {
        self.bytes
    }

    /// The index segment's bytes (count and entries).
    pub fn index_segment(&self) -> &'a [u8] {
        self.entry_bytes
    }

    /// Number of index-segment entries.
    pub fn len(&self) -> usize {
        self.count as usize
    }

    /// True for a container without entries.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// True when the container has attributes.
    pub fn has_attributes(&self) -> bool {
        self.header.ext_info.present()
    }

    /// True when the container has an address segment.
    pub fn has_addresses(&self) -> bool {
        self.header.address.present()
    }

    /// The entries in container order.
    pub fn entries(&self) -> Entries<'a> {
        Entries {
            index: self.entry_bytes,
            attrs: self.attrs,
            at: 4,
            position: 0,
            count: self.count,
        }
    }

    /// Entry `pos` (counted from 0): constant time with an index, a scan
    /// without.
    #[inline]
    pub fn entry(&self, pos: usize) -> Option<Entry<'a>> {
        match &self.index {
            Some(ix) if pos < ix.entries() => self.entry_at(ix, pos),
            Some(_) => None,
            None => self.entries().nth(pos),
        }
    }

    /// Entry `pos` (with an index only).
    fn entry_at(&self, ix: &Index<'a>, pos: usize) -> Option<Entry<'a>> {
        let (head, rest) = self
            .entry_bytes
            .get(ix.offset(pos)..)?
            .split_first_chunk::<ENTRY_HEADER_SIZE>()?;
        let [i0, i1, sub, s0, s1, s2, s3] = *head;
        let size = usize::try_from(u32::from_le_bytes([s0, s1, s2, s3])).ok()?;
        let attr = match self.attrs {
            Some(a) => Some(*a.get(pos)?),
            None => None,
        };
        Some(Entry {
            position: u32::try_from(pos).ok()?,
            index: u16::from_le_bytes([i0, i1]),
            sub,
            data: rest.get(..size)?,
            attr,
        })
    }

    /// Flags of entry `e` of this container (with an index only).
    #[inline]
    fn flags(ix: &Index<'a>, e: &Entry<'_>) -> u8 {
        ix.flags(e.position as usize)
    }

    /// Slots `a..b` of the sorted order holding `index`.
    fn run_of(ix: &Index<'a>, index: u16) -> (usize, usize) {
        let a = ix.lower_bound(index::key_of(index, 0));
        let mut b = a;
        while b < ix.entries() && ix.key_at(b) >> 8 == u32::from(index) {
            b += 1;
        }
        (a, b)
    }

    /// The entries with an index in `first..=last`, in container order.
    /// With an index, a range the container has no entry in costs
    /// O(log n), and an entry outside the range is skipped without being
    /// read whole.
    pub fn entries_in(&self, first: u16, last: u16) -> EntriesIn<'_, 'a> {
        let none = match &self.index {
            Some(ix) => {
                let slot = ix.lower_bound(index::key_of(first, 0));
                slot >= ix.entries() || ix.key_at(slot) > index::key_of(last, 0xFF)
            }
            None => false,
        };
        EntriesIn {
            c: self,
            all: self.entries(),
            pos: if none { self.len() } else { 0 },
            range: (first, last),
        }
    }

    /// True when the container has an entry for `index` with a subindex
    /// other than `sub`.
    pub fn has_other_subs(&self, index: u16, sub: u8) -> bool {
        match &self.index {
            Some(ix) => {
                // The lowest and the highest subindex of `index`.
                let a = ix.lower_bound(index::key_of(index, 0));
                let b = ix.lower_bound(index::key_of(index, 0) + 0x100);
                a < b && (ix.key_at(a) as u8 != sub || ix.key_at(b - 1) as u8 != sub)
            }
            None => self.entries().any(|e| e.index == index && e.sub != sub),
        }
    }

    /// [`Container::has_other_subs`] for entry `e` of this container
    /// (constant time with an index for subindex 0, the case
    /// [`is_pi_candidate`] asks about).
    pub fn entry_has_other_subs(&self, e: &Entry<'_>) -> bool {
        match &self.index {
            Some(ix) if e.sub == 0 => Self::flags(ix, e) & index::OTHER_SUBS != 0,
            _ => self.has_other_subs(e.index, e.sub),
        }
    }

    /// True when entry `e` is a process-image candidate ([`is_pi_candidate`]).
    /// Constant time except for subindex 0 without index, which needs a
    /// scan.
    pub fn is_candidate(&self, e: &Entry<'_>) -> bool {
        e.index >= 0x2000 && (e.sub >= 1 || !self.entry_has_other_subs(e))
    }

    /// Number of process-image candidates among the entries.
    pub fn candidate_count(&self) -> usize {
        match &self.index {
            Some(ix) => ix
                .candidates()
                .unwrap_or_else(|| self.entries().filter(|e| self.is_candidate(e)).count()),
            None => self.entries().filter(|e| self.is_candidate(e)).count(),
        }
    }

    /// The entries in container order, each with its address word:
    /// `Some(offset)` when the address segment places it, `None` when there
    /// is no address segment, the entry is no candidate, or its word is
    /// [`NOT_PLACED`].
    pub fn addressed(&self) -> impl Iterator<Item = (Entry<'a>, Option<u16>)> + '_ {
        let seg = self.segment(self.header.address);
        let mut ordinal = 0usize;
        self.entries().map(move |e| {
            if let Some(ix) = &self.index {
                return (e, ix.word(e.position as usize));
            }
            let word = if self.is_candidate(&e) {
                let w = seg.and_then(|s| le16(s, ordinal.checked_mul(2)?));
                ordinal += 1;
                w.filter(|w| *w != NOT_PLACED)
            } else {
                None
            };
            (e, word)
        })
    }

    /// The address word of entry `e` of this container, as
    /// [`Container::addressed`] pairs it.
    pub fn address_word(&self, e: &Entry<'_>) -> Option<u16> {
        match &self.index {
            Some(ix) => ix.word(e.position as usize),
            None => self
                .addressed()
                .find(|(x, _)| x.position == e.position)
                .and_then(|(_, w)| w),
        }
    }

    /// The first entry with the index and subindex of entry `e`.
    pub fn first_occurrence(&self, e: &Entry<'a>) -> Entry<'a> {
        let same = |x: &Entry<'_>| x.index == e.index && x.sub == e.sub;
        match &self.index {
            Some(ix) if Self::flags(ix, e) & index::FIRST_OF_KEY != 0 => *e,
            Some(ix) => {
                let slot = ix.lower_bound(index::key_of(e.index, e.sub));
                self.entry_at(ix, ix.position(slot))
                    .filter(same)
                    .unwrap_or(*e)
            }
            None => self.entries().find(same).unwrap_or(*e),
        }
    }

    /// True when entry `e` is the first one with its index and subindex.
    #[inline]
    pub fn is_first_occurrence(&self, e: &Entry<'_>) -> bool {
        match &self.index {
            Some(ix) => Self::flags(ix, e) & index::FIRST_OF_KEY != 0,
            None => self.scan_is_first_occurrence(e),
        }
    }

    #[inline(never)]
    fn scan_is_first_occurrence(&self, e: &Entry<'_>) -> bool {
        self.entries()
            .find(|x| x.index == e.index && x.sub == e.sub)
            .is_some_and(|x| x.position == e.position)
    }

    /// [`Container::is_first_occurrence`] of entry `pos`: constant time
    /// with an index, without reading the entry.
    #[inline]
    pub fn is_first_occurrence_at(&self, pos: usize) -> bool {
        match &self.index {
            Some(ix) => ix.flags(pos) & index::FIRST_OF_KEY != 0,
            None => self
                .entry(pos)
                .is_some_and(|e| self.is_first_occurrence(&e)),
        }
    }

    /// The last entry for `index`/`sub`, if any.
    pub fn last_occurrence(&self, index: u16, sub: u8) -> Option<Entry<'a>> {
        let same = |x: &Entry<'_>| x.index == index && x.sub == sub;
        match &self.index {
            Some(ix) => {
                let slot = ix.lower_bound(index::key_of(index, sub) + 1);
                let last = slot.checked_sub(1)?;
                self.entry_at(ix, ix.position(last)).filter(same)
            }
            None => self.entries().filter(same).last(),
        }
    }

    /// True when entry `e` is the last one with its index and subindex.
    #[inline]
    pub fn is_last_occurrence(&self, e: &Entry<'_>) -> bool {
        match &self.index {
            Some(ix) => Self::flags(ix, e) & index::LAST_OF_KEY != 0,
            None => self
                .last_occurrence(e.index, e.sub)
                .is_some_and(|l| l.position == e.position),
        }
    }

    /// True when entry `e` is the first one with its index.
    #[inline]
    pub fn is_first_of_index(&self, e: &Entry<'_>) -> bool {
        match &self.index {
            Some(ix) => Self::flags(ix, e) & index::FIRST_OF_INDEX != 0,
            None => self.first_position(e.index) == Some(e.position),
        }
    }

    /// True when the container has an entry for subindex 0 of the index of
    /// entry `e` (constant time with an index when `e` is the first entry
    /// of its index).
    #[inline]
    pub fn has_sub_zero(&self, e: &Entry<'_>) -> bool {
        match &self.index {
            Some(ix) if Self::flags(ix, e) & index::FIRST_OF_INDEX != 0 => {
                Self::flags(ix, e) & index::ZERO_SUB != 0
            }
            _ => self.last_occurrence(e.index, 0).is_some(),
        }
    }

    /// Position of the first entry with `index`, if any.
    pub fn first_position(&self, index: u16) -> Option<u32> {
        match &self.index {
            Some(ix) => {
                let (a, b) = Self::run_of(ix, index);
                (a..b)
                    .map(|s| ix.position(s))
                    .find(|p| ix.flags(*p) & index::FIRST_OF_INDEX != 0)
                    .and_then(|p| u32::try_from(p).ok())
            }
            None => self
                .entries()
                .find(|x| x.index == index)
                .map(|x| x.position),
        }
    }

    /// The subindices the container has for `index`.
    pub fn subindices(&self, index: u16) -> Subindices {
        let mut s = Subindices::default();
        match &self.index {
            Some(ix) => {
                let mut slot = ix.lower_bound(index::key_of(index, 0));
                let mut prev = None;
                while slot < ix.entries() {
                    let k = ix.key_at(slot);
                    if k >> 8 != u32::from(index) {
                        break;
                    }
                    s.count_key(&mut prev, k);
                    slot += 1;
                }
            }
            None => {
                for e in self.entries().filter(|e| e.index == index) {
                    if self.first_occurrence(&e).position == e.position {
                        s.distinct += 1;
                    }
                    s.has_zero |= e.sub == 0;
                    s.highest = s.highest.max(e.sub);
                }
            }
        }
        s
    }

    /// The indices of the entries, each once, in ascending order.
    pub fn indices(&self) -> impl Iterator<Item = u16> + '_ {
        let mut last: Option<u16> = None;
        let mut slot = 0usize;
        core::iter::from_fn(move || {
            let next = match &self.index {
                Some(ix) => {
                    while slot < ix.entries()
                        && last.is_some_and(|l| (ix.key_at(slot) >> 8) as u16 == l)
                    {
                        slot += 1;
                    }
                    if slot >= ix.entries() {
                        return None;
                    }
                    (ix.key_at(slot) >> 8) as u16
                }
                None => self
                    .entries()
                    .filter(|e| last.is_none_or(|l| e.index > l))
                    .map(|e| e.index)
                    .min()?,
            };
            last = Some(next);
            Some(next)
        })
    }

    /// The indices of the entries in ascending order, each with its
    /// subindices ([`Container::subs_of`]).
    pub fn objects(&self) -> impl Iterator<Item = SubsOf<'_, 'a>> + '_ {
        let mut slot = 0usize;
        let mut indices = self.indices();
        core::iter::from_fn(move || match &self.index {
            Some(ix) => {
                if slot >= ix.entries() {
                    return None;
                }
                let index = (ix.key_at(slot) >> 8) as u16;
                let start = slot;
                while slot < ix.entries() && ix.key_at(slot) >> 8 == u32::from(index) {
                    slot += 1;
                }
                Some(SubsOf {
                    c: self,
                    index,
                    last: None,
                    slot: start,
                    end: slot,
                })
            }
            None => indices.next().map(|i| self.subs_of(i)),
        })
    }

    /// The subindices of `index` in ascending order, each as its first and
    /// its last entry.
    pub fn subs_of(&self, index: u16) -> SubsOf<'_, 'a> {
        let (slot, end) = match &self.index {
            Some(ix) => Self::run_of(ix, index),
            None => (0, 0),
        };
        SubsOf {
            c: self,
            index,
            last: None,
            slot,
            end,
        }
    }

    /// The process-image parameters, when the segment is present.
    pub fn pi_params(&self) -> Option<PiParams> {
        let s = self.segment(self.header.pi_param)?;
        Some(PiParams {
            total: le32(s, 0)?,
            input_offset: le32(s, 4)?,
            input_size: le32(s, 8)?,
            output_offset: le32(s, 12)?,
            output_size: le32(s, 16)?,
        })
    }
}

/// True when attribute `a` is allowed for `len` bytes of data.
#[inline]
fn attribute_fits(a: u8, len: usize) -> bool {
    if a & attr::RESERVED != 0 {
        return false;
    }
    match a & attr::TYPE_MASK {
        0 | attr::VISIBLE_STRING => true,
        attr::BOOLEAN => len == 1,
        attr::NUMERIC => (1..=8).contains(&len),
        _ => false,
    }
}

/// Iterator over the entries of a validated container.
#[derive(Clone, Debug)]
pub struct Entries<'a> {
    index: &'a [u8],
    attrs: Option<&'a [u8]>,
    at: usize,
    position: u32,
    count: u32,
}

impl<'a> Iterator for Entries<'a> {
    type Item = Entry<'a>;

    fn next(&mut self) -> Option<Entry<'a>> {
        if self.position >= self.count {
            return None;
        }
        let (head, rest) = self
            .index
            .get(self.at..)?
            .split_first_chunk::<ENTRY_HEADER_SIZE>()?;
        let [i0, i1, sub, s0, s1, s2, s3] = *head;
        let index = u16::from_le_bytes([i0, i1]);
        let size = usize::try_from(u32::from_le_bytes([s0, s1, s2, s3])).ok()?;
        let data = rest.get(..size)?;
        let end = self.at + ENTRY_HEADER_SIZE + size;
        let attr = match self.attrs {
            Some(a) => Some(*a.get(self.position as usize)?),
            None => None,
        };
        let e = Entry {
            position: self.position,
            index,
            sub,
            data,
            attr,
        };
        self.at = end;
        self.position += 1;
        Some(e)
    }
}

/// Iterator over the entries of a container with an index in a range
/// ([`Container::entries_in`]).
#[derive(Clone, Debug)]
pub struct EntriesIn<'c, 'a> {
    c: &'c Container<'a>,
    all: Entries<'a>,
    pos: usize,
    range: (u16, u16),
}

impl<'a> Iterator for EntriesIn<'_, 'a> {
    type Item = Entry<'a>;

    fn next(&mut self) -> Option<Entry<'a>> {
        let (first, last) = self.range;
        let ix = match &self.c.index {
            Some(ix) if self.range != (0x0000, 0xFFFF) => ix,
            _ => return self.all.find(|e| (first..=last).contains(&e.index)),
        };
        let segment = self.c.index_segment();
        while self.pos < ix.entries() {
            let pos = self.pos;
            self.pos += 1;
            if le16(segment, ix.offset(pos)).is_some_and(|i| (first..=last).contains(&i)) {
                return self.c.entry_at(ix, pos);
            }
        }
        None
    }
}

/// Iterator over the subindices of one index ([`Container::subs_of`]).
#[derive(Clone, Debug)]
pub struct SubsOf<'c, 'a> {
    c: &'c Container<'a>,
    index: u16,
    /// Without index: the subindex returned last.
    last: Option<u8>,
    /// With index: the slots of the index still to go.
    slot: usize,
    end: usize,
}

impl SubsOf<'_, '_> {
    /// The index.
    pub fn index(&self) -> u16 {
        self.index
    }

    /// The count subindex the object lacks: `Some(highest subindex)` when
    /// the container has subindices of the index but not subindex 0
    /// ([`Subindices::lacks_count`]), else `None`. Constant time with an
    /// index; ask before iterating.
    pub fn missing_count(&self) -> Option<u8> {
        let Some(ix) = &self.c.index else {
            let s = self.c.subindices(self.index);
            return s.lacks_count().then_some(s.highest);
        };
        if self.slot >= self.end || ix.key_at(self.slot) & 0xFF == 0 {
            return None;
        }
        Some(ix.key_at(self.end - 1) as u8)
    }

    /// The position of an entry of the index, with an index and before
    /// iterating (`None` otherwise).
    pub fn entry_position(&self) -> Option<u32> {
        let ix = self.c.index.as_ref()?;
        (self.slot < self.end)
            .then(|| u32::try_from(ix.position(self.slot)).ok())
            .flatten()
    }

    /// [`Container::subindices`] of the index (without a second search
    /// when the container has an index).
    pub fn subindices(&self) -> Subindices {
        let Some(ix) = &self.c.index else {
            return self.c.subindices(self.index);
        };
        let mut s = Subindices::default();
        let mut prev = None;
        for slot in self.slot..self.end {
            let k = ix.key_at(slot);
            s.count_key(&mut prev, k);
        }
        s
    }
}

impl<'a> Iterator for SubsOf<'_, 'a> {
    type Item = (Entry<'a>, Entry<'a>);

    fn next(&mut self) -> Option<(Entry<'a>, Entry<'a>)> {
        let c = self.c;
        let Some(ix) = &c.index else {
            let index = self.index;
            let sub = c
                .entries()
                .filter(|e| e.index == index && self.last.is_none_or(|l| e.sub > l))
                .map(|e| e.sub)
                .min()?;
            self.last = Some(sub);
            let e = c.last_occurrence(index, sub)?;
            return Some((c.first_occurrence(&e), e));
        };
        if self.slot >= self.end {
            return None;
        }
        let pos = ix.position(self.slot);
        let first = c.entry_at(ix, pos)?;
        let e = if ix.flags(pos) & index::LAST_OF_KEY != 0 {
            first
        } else {
            let k = ix.key_at(self.slot);
            while self.slot + 1 < self.end && ix.key_at(self.slot + 1) == k {
                self.slot += 1;
            }
            c.entry_at(ix, ix.position(self.slot))?
        };
        self.slot += 1;
        Some((first, e))
    }
}

/// The entries of an index segment that [`Container::parse`] accepted
/// before (a copy kept by the dynamic OD), without attributes. A segment
/// that does not parse simply ends the iteration early.
pub fn entries_of_index_segment(index: &[u8]) -> Entries<'_> {
    Entries {
        index,
        attrs: None,
        at: 4,
        position: 0,
        count: le32(index, 0).unwrap_or(0),
    }
}

// ---------------------------------------------------------------------
// Network variables (seed chapter 6, CiA 302/405)
// ---------------------------------------------------------------------

/// Direction of a network variable, i.e. its area of the process image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PiArea {
    /// 0xA000–0xA47F: inputs (received, RPDO data).
    Input,
    /// 0xA480–0xA8FF: outputs (sent, TPDO data).
    Output,
}

/// The data types of the network-variable ranges in the order of seed
/// table 2; each range is 0x40 indices wide, inputs from 0xA000, outputs
/// from 0xA480.
const NETVAR_TYPES: [DataType; 18] = [
    DataType::Int8,
    DataType::UInt8,
    DataType::Bool,
    DataType::Int16,
    DataType::UInt16,
    DataType::Int24,
    DataType::UInt24,
    DataType::Int32,
    DataType::UInt32,
    DataType::Real32,
    DataType::UInt40,
    DataType::Int40,
    DataType::UInt48,
    DataType::Int48,
    DataType::UInt56,
    DataType::Int56,
    DataType::Int64,
    DataType::UInt64,
];

/// First input network variable.
pub const NETVAR_INPUT_BASE: u16 = 0xA000;
/// First output network variable.
pub const NETVAR_OUTPUT_BASE: u16 = 0xA480;
/// Indices per type range.
pub const NETVAR_RANGE: u16 = 0x40;
/// Variables one index holds (subindices 1..=254, seed chapter 6).
pub const NETVAR_PER_INDEX: u32 = 254;

/// What seed table 2 says about an index of 0xA000–0xA8FF.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NetVar {
    /// Input or output area.
    pub area: PiArea,
    /// Data type of every variable of the index.
    pub typ: DataType,
    /// First index of the type's range (0xA4C0 for UNSIGNED8 outputs).
    pub range_start: u16,
}

/// True for the network-variable indices (0xA000–0xAFFF), which the
/// dynamic OD always creates as numeric, read-write, mappable variables.
pub const fn is_network_variable(index: u16) -> bool {
    index >= 0xA000 && index <= 0xAFFF
}

/// Seed table 2 for `index`; `None` outside 0xA000–0xA8FF.
pub fn network_variable(index: u16) -> Option<NetVar> {
    let (area, base) = match index {
        NETVAR_INPUT_BASE..0xA480 => (PiArea::Input, NETVAR_INPUT_BASE),
        NETVAR_OUTPUT_BASE..0xA900 => (PiArea::Output, NETVAR_OUTPUT_BASE),
        _ => return None,
    };
    let k = (index - base) / NETVAR_RANGE;
    let typ = *NETVAR_TYPES.get(usize::from(k))?;
    Some(NetVar {
        area,
        typ,
        range_start: base + k * NETVAR_RANGE,
    })
}

/// Bytes one variable of `typ` takes in memory: the width of its C type
/// (`tObdInteger24` is a `long`, the 40..56-bit types are `QWORD`), so that
/// every variable of the process image is an ordinary C variable.
pub const fn element_size(typ: DataType) -> usize {
    match typ.wire_size() {
        Some(1) => 1,
        Some(2) => 2,
        Some(3) | Some(4) => 4,
        Some(5..=8) => 8,
        Some(n) => n,
        None => 0,
    }
}

/// The CiA 302/405 offset rule (seed chapter 6): the variable
/// `index`/`sub` is element `(index - range_start) * 254 + sub - 1` of the
/// array of its type, so its offset inside its area is that element times
/// the element size. `None` for subindex 0 and indices outside the table.
pub fn rule_offset(index: u16, sub: u8) -> Option<(PiArea, u32, usize)> {
    let nv = network_variable(index)?;
    if sub == 0 || u32::from(sub) > NETVAR_PER_INDEX {
        return None;
    }
    let element = u32::from(index - nv.range_start) * NETVAR_PER_INDEX + u32::from(sub) - 1;
    let size = element_size(nv.typ);
    Some((nv.area, element.checked_mul(size as u32)?, size))
}

/// Where the areas lie when no parameter segment says so: inputs from 0,
/// outputs after them on the next multiple of 8 (so that every variable of
/// the output area keeps its natural alignment).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PiLayout {
    /// Bytes the input variables need (from offset 0).
    pub input_size: u32,
    /// Bytes the output variables need.
    pub output_size: u32,
}

impl PiLayout {
    /// Takes the variables `(index, sub)` into account (others are
    /// ignored).
    pub fn add(&mut self, index: u16, sub: u8) {
        if let Some((area, off, size)) = rule_offset(index, sub) {
            let end = off.saturating_add(size as u32);
            match area {
                PiArea::Input => self.input_size = self.input_size.max(end),
                PiArea::Output => self.output_size = self.output_size.max(end),
            }
        }
    }

    /// Offset of the output area.
    pub fn output_offset(&self) -> u32 {
        self.input_size.saturating_add(7) & !7
    }

    /// Start of `area`.
    pub fn area_offset(&self, area: PiArea) -> u32 {
        match area {
            PiArea::Input => 0,
            PiArea::Output => self.output_offset(),
        }
    }

    /// The parameters (whole image, both windows).
    pub fn params(&self) -> PiParams {
        let out = self.output_offset();
        PiParams {
            total: out.saturating_add(self.output_size),
            input_offset: 0,
            input_size: self.input_size,
            output_offset: out,
            output_size: self.output_size,
        }
    }

    /// Absolute offset of variable `index`/`sub` by the rule.
    pub fn place(&self, index: u16, sub: u8) -> Option<(u32, usize)> {
        let (area, off, size) = rule_offset(index, sub)?;
        Some((self.area_offset(area).checked_add(off)?, size))
    }
}

// ---------------------------------------------------------------------
// Encoding (host tool, tests)
// ---------------------------------------------------------------------

/// One entry to encode.
#[derive(Clone, Copy, Debug)]
pub struct EntrySpec<'a> {
    /// Index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
    /// Value in CANopen byte order.
    pub data: &'a [u8],
    /// Attribute byte.
    pub attr: u8,
}

/// Why [`encode`] could not write a container.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EncodeError {
    /// The output buffer is smaller than [`encoded_len`].
    BufferTooSmall,
    /// The container would exceed 4 GiB.
    TooLarge,
}

/// Size of the container [`encode`] writes.
pub fn encoded_len(
    entries: &[EntrySpec<'_>],
    addresses: Option<&[u16]>,
    attributes: bool,
    pi: Option<&PiParams>,
) -> Option<usize> {
    let mut n = HEADER_SIZE.checked_add(4)?;
    for e in entries {
        n = n
            .checked_add(ENTRY_HEADER_SIZE)?
            .checked_add(e.data.len())?;
    }
    if let Some(a) = addresses {
        n = n.checked_add(a.len().checked_mul(2)?)?;
    }
    if attributes {
        n = n.checked_add(entries.len())?;
    }
    if pi.is_some() {
        n = n.checked_add(PI_PARAM_SIZE)?;
    }
    Some(n)
}

/// Writes a container with the segments in the order of seed Bild 3,
/// without gaps. `addresses` (one WORD per candidate) and `pi` are
/// optional; `attributes` false leaves out the extended info segment.
/// Returns the number of bytes written. The caller is responsible for
/// passing one address word per candidate ([`Container::parse`] checks).
pub fn encode(
    entries: &[EntrySpec<'_>],
    addresses: Option<&[u16]>,
    attributes: bool,
    pi: Option<&PiParams>,
    out: &mut [u8],
) -> Result<usize, EncodeError> {
    let total = encoded_len(entries, addresses, attributes, pi).ok_or(EncodeError::TooLarge)?;
    let total32 = u32::try_from(total).map_err(|_| EncodeError::TooLarge)?;
    let out = out.get_mut(..total).ok_or(EncodeError::BufferTooSmall)?;
    out.fill(0);
    let mut w = Writer { out, at: 0 };
    w.u32(total32);
    w.u16(VERSION);
    let used = 1 + u16::from(addresses.is_some()) + u16::from(attributes) + u16::from(pi.is_some());
    w.u16(used);
    let index_size = entries
        .iter()
        .map(|e| ENTRY_HEADER_SIZE + e.data.len())
        .sum::<usize>()
        + 4;
    let addr_size = addresses.map_or(0, |a| a.len() * 2);
    let ext_size = if attributes { entries.len() } else { 0 };
    let pi_size = if pi.is_some() { PI_PARAM_SIZE } else { 0 };
    let mut offset = HEADER_SIZE;
    for size in [index_size, addr_size, ext_size, pi_size] {
        // Sizes were summed into `total` above, which fits 32 bits.
        if size == 0 {
            w.u32(0);
            w.u32(0);
        } else {
            w.u32(offset as u32);
            w.u32(size as u32);
            offset += size;
        }
    }
    w.u32(entries.len() as u32);
    for e in entries {
        w.u16(e.index);
        w.bytes(&[e.sub]);
        w.u32(e.data.len() as u32);
        w.bytes(e.data);
    }
    for a in addresses.unwrap_or(&[]) {
        w.u16(*a);
    }
    if attributes {
        for e in entries {
            w.bytes(&[e.attr]);
        }
    }
    if let Some(p) = pi {
        w.bytes(&p.to_bytes());
    }
    Ok(total)
}

struct Writer<'b> {
    out: &'b mut [u8],
    at: usize,
}

impl Writer<'_> {
    fn bytes(&mut self, b: &[u8]) {
        let end = self.at + b.len();
        if let Some(dst) = self.out.get_mut(self.at..end) {
            dst.copy_from_slice(b);
        }
        self.at = end;
    }
    fn u16(&mut self, v: u16) {
        self.bytes(&v.to_le_bytes());
    }
    fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
}

#[cfg(test)]
mod tests;
