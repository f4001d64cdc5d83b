//! An index of the entries of a container, built once in scratch memory
//! the caller lends ([`Container::parse_indexed`]), so that the questions
//! the dynamic OD asks about the entries (first and last occurrence of a
//! subindex, the subindices of an object in ascending order, whether an
//! object has other subindices, the address word of an entry) cost O(1)
//! or O(log n) instead of a pass over the container. Building it costs
//! O(n log n) (a merge sort that leaves runs already in order alone, so a
//! sorted container costs O(n)).
//!
//! # Layout (at the end of the scratch)
//! `n` entries; positions and offsets take `w` = 2 bytes when the index
//! segment is shorter than 64 KiB, else 4 (little-endian, no alignment
//! needed):
//!
//! | region | size | content |
//! |---|---|---|
//! | order | n × (3 + w) | (subindex, index, position) of every entry, sorted by index, subindex and position |
//! | offsets | n × w | offset of each entry in the index segment, by position |
//! | flags | n | [`FIRST_OF_KEY`] ... [`ZERO_SUB`], by position |
//! | words | 2n, only with an address segment | address word of each entry, by position |
//!
//! While the order is sorted, the offsets, flags and words hold the merge
//! buffer (n / 2 elements). See [`scratch_len`].

use core::fmt;

use super::{Container, ENTRY_HEADER_SIZE, NOT_PLACED, is_pi_candidate, le16};

/// The entry is the first one of its (index, subindex).
pub(super) const FIRST_OF_KEY: u8 = 0x01;
/// The entry is the last one of its (index, subindex).
pub(super) const LAST_OF_KEY: u8 = 0x02;
/// The entry is the first one of its index.
pub(super) const FIRST_OF_INDEX: u8 = 0x04;
/// On an entry of subindex 0: its index has another subindex in the
/// container (the only entries that question matters for, see
/// [`is_pi_candidate`]).
pub(super) const OTHER_SUBS: u8 = 0x08;
/// On the first entry of an index: the index has subindex 0 in the
/// container.
pub(super) const ZERO_SUB: u8 = 0x10;

/// Bytes of the key in an element of the order.
const KEY: usize = 3;

/// Bytes per position or offset for an index segment of `segment_len`.
const fn width(segment_len: usize) -> usize {
    if segment_len <= 0xFFFF { 2 } else { 4 }
}

/// Scratch bytes an index of `n` entries of an index segment of
/// `segment_len` bytes needs (`words`: the container has an address
/// segment): 8n (10n with words) below 64 KiB of index segment, 12n (14n)
/// from there on. `None` on overflow.
pub(super) fn scratch_len(n: usize, segment_len: usize, words: bool) -> Option<usize> {
    let w = width(segment_len);
    let per_entry = (KEY + w) + w + 1 + if words { 2 } else { 0 };
    n.checked_mul(per_entry)
}

/// The key of `index`/`sub`: index << 8 | subindex.
pub(super) const fn key_of(index: u16, sub: u8) -> u32 {
    (index as u32) << 8 | sub as u32
}

/// Width of positions and offsets: 2 or 4 bytes, little-endian.
trait Width {
    /// Bytes.
    const W: usize;
    /// One element of the order (key and position).
    type Elem: Copy + Default + AsRef<[u8]> + AsMut<[u8]>;
    /// The number in `b` (`W` bytes; 0 for anything else).
    fn read(b: &[u8]) -> usize;
    /// Writes `v` into `b` (`W` bytes; `v` fits: positions and offsets are
    /// below the segment length, which chose the width).
    fn write(b: &mut [u8], v: usize);
}

/// Index segments below 64 KiB.
struct W2;
/// Larger index segments.
struct W4;

impl Width for W2 {
    const W: usize = 2;
    type Elem = [u8; KEY + 2];
    fn read(b: &[u8]) -> usize {
        match *b {
            [x, y] => usize::from(u16::from_le_bytes([x, y])),
            _ => 0,
        }
    }
    fn write(b: &mut [u8], v: usize) {
        if let Some(d) = b.first_chunk_mut::<2>() {
            *d = (v as u16).to_le_bytes();
        }
    }
}

impl Width for W4 {
    const W: usize = 4;
    type Elem = [u8; KEY + 4];
    fn read(b: &[u8]) -> usize {
        match *b {
            [x, y, z, t] => u32::from_le_bytes([x, y, z, t]) as usize,
            _ => 0,
        }
    }
    fn write(b: &mut [u8], v: usize) {
        if let Some(d) = b.first_chunk_mut::<4>() {
            *d = (v as u32).to_le_bytes();
        }
    }
}

/// The key in the first three bytes of an element.
fn read_key(b: &[u8]) -> u32 {
    match *b {
        [s, lo, hi, ..] => u32::from_le_bytes([s, lo, hi, 0]),
        _ => 0,
    }
}

/// Calls the width-generic function `f` with the index's width (`w`, 2
/// or 4 bytes): the one place that turns the run-time width into a type.
macro_rules! by_width {
    ($w:expr, $($f:ident)::+($($arg:expr),*)) => {
        if $w == 2 {
            $($f)::+::<W2>($($arg),*)
        } else {
            $($f)::+::<W4>($($arg),*)
        }
    };
}

/// Number `i` of an array of numbers.
fn get<X: Width>(mem: &[u8], i: usize) -> usize {
    mem.get(i * X::W..i * X::W + X::W).map_or(0, X::read)
}

/// Sets number `i` of an array of numbers.
fn put<X: Width>(mem: &mut [u8], i: usize, v: usize) {
    if let Some(dst) = mem.get_mut(i * X::W..i * X::W + X::W) {
        X::write(dst, v);
    }
}

/// Element `i` of the order: (key, position).
fn elem<X: Width>(mem: &[u8], i: usize) -> (u32, usize) {
    let at = i * (KEY + X::W);
    match mem.get(at..at + KEY + X::W) {
        Some(e) => (read_key(e), e.get(KEY..).map_or(0, X::read)),
        None => (0, 0),
    }
}

/// Key of element `i` of the order.
fn elem_key<X: Width>(mem: &[u8], i: usize) -> u32 {
    let at = i * (KEY + X::W);
    mem.get(at..at + KEY).map_or(0, read_key)
}

/// Sets element `i` of the order.
fn set_elem<X: Width>(mem: &mut [u8], i: usize, (key, pos): (u32, usize)) {
    let at = i * (KEY + X::W);
    if let Some((k, p)) = mem
        .get_mut(at..at + KEY + X::W)
        .and_then(|e| e.split_first_chunk_mut::<KEY>())
    {
        let [s, lo, hi, _] = key.to_le_bytes();
        *k = [s, lo, hi];
        X::write(p, pos);
    }
}

/// Elements sorted by insertion before the merges begin.
const BLOCK: usize = 16;

/// Sorts the `n` elements of `order` (initially in container order) by
/// key, stably, so that equal keys stay in container order: blocks of
/// [`BLOCK`] elements by insertion (at most `BLOCK` moves per element),
/// then bottom-up merges; `buf` holds at least `n / 2` elements. Two
/// neighbouring runs already in order are left alone, so a sorted
/// container costs one comparison per element.
fn merge_sort<X: Width>(order: &mut [u8], buf: &mut [u8], n: usize) {
    let e = KEY + X::W;
    let mut lo = 0usize;
    while lo < n {
        let hi = (lo + BLOCK).min(n);
        let mut last = elem_key::<X>(order, lo);
        for i in lo + 1..hi {
            let k = elem_key::<X>(order, i);
            if last <= k {
                last = k;
                continue;
            }
            // Behind the last element not above it (stable).
            let at = tail_start(lo, i - 1, |x| elem_key::<X>(order, x) > k);
            let mut tmp = X::Elem::default();
            copy(Some(tmp.as_mut()), order.get(i * e..(i + 1) * e));
            if (i + 1) * e <= order.len() {
                order.copy_within(at * e..i * e, (at + 1) * e);
            }
            copy(order.get_mut(at * e..(at + 1) * e), Some(tmp.as_ref()));
        }
        lo = hi;
    }
    let mut run = BLOCK;
    while run < n {
        let mut lo = 0usize;
        while lo + run < n {
            let mid = lo + run;
            let hi = mid.saturating_add(run).min(n);
            if elem_key::<X>(order, mid - 1) > elem_key::<X>(order, mid) {
                merge::<X>(order, buf, (lo, mid, hi));
            }
            lo = hi;
        }
        run = run.saturating_mul(2);
    }
}

/// The start of the tail of `lo..hi` whose elements satisfy `after`
/// (which holds for a suffix of the range): searched from the back with
/// growing steps, then halving, so a tail of `t` elements costs
/// O(log t) probes.
fn tail_start(lo: usize, hi: usize, after: impl Fn(usize) -> bool) -> usize {
    let mut start = hi;
    let mut floor = lo;
    let mut step = 1usize;
    while start > lo {
        let probe = start.saturating_sub(step).max(lo);
        if after(probe) {
            start = probe;
            step = step.saturating_mul(2);
        } else {
            floor = probe + 1;
            break;
        }
    }
    let (mut a, mut b) = (floor, start);
    while a < b {
        let m = a + (b - a) / 2;
        if after(m) {
            b = m;
        } else {
            a = m + 1;
        }
    }
    a
}

/// Copies `src` into `dst` when both have the same length.
fn copy(dst: Option<&mut [u8]>, src: Option<&[u8]>) {
    if let (Some(d), Some(s)) = (dst, src) {
        if d.len() == s.len() {
            d.copy_from_slice(s);
        }
    }
}

/// Merges the sorted runs `order[lo..mid]` and `order[mid..hi]` (the last
/// element of the left run is greater than the first of the right run).
/// The elements of the right run not below the left run's last stay where
/// they are; the others (never more than the left run, so at most n / 2)
/// move to `buf`, then both runs are merged from the back, a block of
/// elements of one run at a time. Equal keys keep the left run first.
fn merge<X: Width>(order: &mut [u8], buf: &mut [u8], (lo, mid, hi): (usize, usize, usize)) {
    let e = KEY + X::W;
    let left_last = elem_key::<X>(order, mid - 1);
    let hi = tail_start(mid, hi, |x| elem_key::<X>(order, x) >= left_last);
    let r = hi - mid;
    copy(buf.get_mut(..r * e), order.get(mid * e..hi * e));
    // order[lo..i] and buf[..j] are still to be placed, order[i + j..hi]
    // is done.
    let mut i = mid;
    let mut j = r;
    while j > 0 {
        // The left run's elements above the right run's last go behind it.
        let right_last = elem_key::<X>(buf, j - 1);
        let t = tail_start(lo, i, |x| elem_key::<X>(order, x) > right_last);
        if t < i && (i + j) * e <= order.len() {
            order.copy_within(t * e..i * e, (t + j) * e);
        }
        i = t;
        if i == lo {
            copy(order.get_mut(lo * e..(lo + j) * e), buf.get(..j * e));
            return;
        }
        // The right run's elements not below the left run's last follow.
        let left_last = elem_key::<X>(order, i - 1);
        let u = tail_start(0, j, |x| elem_key::<X>(buf, x) >= left_last);
        copy(
            order.get_mut((i + u) * e..(i + j) * e),
            buf.get(u * e..j * e),
        );
        j = u;
    }
}

/// First of the `n` slots of `order` whose key is not below `key`.
fn lower_bound<X: Width>(order: &[u8], n: usize, key: u32) -> usize {
    let (mut lo, mut hi) = (0usize, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if elem_key::<X>(order, mid) < key {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The index of one container (see the module documentation).
#[derive(Clone, Copy)]
pub(super) struct Index<'a> {
    order: &'a [u8],
    offsets: &'a [u8],
    flags: &'a [u8],
    words: &'a [u8],
    w: usize,
    n: usize,
    /// Counted while building only with an address segment.
    candidates: Option<usize>,
    len: usize,
}

impl fmt::Debug for Index<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Index")
            .field("entries", &self.n)
            .field("bytes", &self.len)
            .finish()
    }
}

impl<'a> Index<'a> {
    /// Builds the index of `c` (whose entries [`Container::parse`] walked
    /// already) at the end of `scratch`. `None` when the scratch is too
    /// small.
    pub(super) fn build(c: &Container<'a>, scratch: &'a mut [u8]) -> Option<Index<'a>> {
        by_width!(width(c.index_segment().len()), Self::build_w(c, scratch))
    }

    /// [`Index::build`] with positions and offsets of width `X`.
    fn build_w<X: Width>(c: &Container<'a>, scratch: &'a mut [u8]) -> Option<Index<'a>> {
        let segment = c.index_segment();
        let n = c.len();
        let w = X::W;
        let with_words = c.has_addresses();
        let len = scratch_len(n, segment.len(), with_words)?;
        let start = scratch.len().checked_sub(len)?;
        let mem = scratch.get_mut(start..)?;
        let (order, rest) = mem.split_at_mut_checked(n * (KEY + w))?;

        // The elements in container order, then sorted (the rest of the
        // index is the buffer).
        let mut at = 4usize;
        for pos in 0..n {
            let (head, _) = segment
                .get(at..)?
                .split_first_chunk::<ENTRY_HEADER_SIZE>()?;
            let [i0, i1, sub, s0, s1, s2, s3] = *head;
            set_elem::<X>(order, pos, (u32::from_le_bytes([sub, i0, i1, 0]), pos));
            let size = usize::try_from(u32::from_le_bytes([s0, s1, s2, s3])).ok()?;
            at = at.checked_add(ENTRY_HEADER_SIZE)?.checked_add(size)?;
        }
        merge_sort::<X>(order, rest, n);
        let order: &'a [u8] = order;

        let (offsets, rest) = rest.split_at_mut_checked(n * w)?;
        let (flags, words) = rest.split_at_mut_checked(n)?;
        let mut at = 4usize;
        for pos in 0..n {
            put::<X>(offsets, pos, at);
            let size = usize::try_from(super::le32(segment, at + 3)?).ok()?;
            at = at.checked_add(ENTRY_HEADER_SIZE)?.checked_add(size)?;
        }
        flags.fill(0);
        let mut flag = |pos: usize, f: u8| {
            if let Some(x) = flags.get_mut(pos) {
                *x |= f;
            }
        };
        // One pass over the runs of each index in sorted order.
        let mut a = 0usize;
        while a < n {
            let index = elem_key::<X>(order, a) >> 8;
            let mut b = a;
            let mut prev = u32::MAX;
            let mut prev_pos = 0usize;
            let mut distinct = 0usize;
            let mut first = usize::MAX;
            while b < n {
                let (k, pos) = elem::<X>(order, b);
                if k >> 8 != index {
                    break;
                }
                if k != prev {
                    if b > a {
                        flag(prev_pos, LAST_OF_KEY);
                    }
                    flag(pos, FIRST_OF_KEY);
                    first = first.min(pos);
                    distinct += 1;
                    prev = k;
                }
                prev_pos = pos;
                b += 1;
            }
            flag(prev_pos, LAST_OF_KEY);
            let zero = elem_key::<X>(order, a) & 0xFF == 0;
            flag(
                first,
                if zero {
                    FIRST_OF_INDEX | ZERO_SUB
                } else {
                    FIRST_OF_INDEX
                },
            );
            // Subindex 0 sorts first.
            if distinct > 1 {
                let mut s = a;
                while s < b && elem_key::<X>(order, s) & 0xFF == 0 {
                    flag(elem::<X>(order, s).1, OTHER_SUBS);
                    s += 1;
                }
            }
            a = b;
        }
        let flags: &'a [u8] = flags;
        let offsets: &'a [u8] = offsets;

        // With an address segment: the candidates in container order, each
        // with its word.
        let mut candidates = 0usize;
        let words: &'a [u8] = if with_words {
            let words = words.get_mut(..n * 2)?;
            let address = c.segment(c.header.address);
            for pos in 0..n {
                let off = get::<X>(offsets, pos);
                let (index, sub) = (le16(segment, off)?, *segment.get(off + 2)?);
                let other = flags.get(pos).is_some_and(|f| f & OTHER_SUBS != 0);
                let mut word = NOT_PLACED;
                if is_pi_candidate(index, sub, other) {
                    word = address
                        .and_then(|s| le16(s, candidates.checked_mul(2)?))
                        .unwrap_or(NOT_PLACED);
                    candidates += 1;
                }
                if let Some(dst) = words.get_mut(pos * 2..pos * 2 + 2) {
                    dst.copy_from_slice(&word.to_ne_bytes());
                }
            }
            words
        } else {
            &[]
        };
        Some(Index {
            order,
            offsets,
            flags,
            words,
            w,
            n,
            candidates: with_words.then_some(candidates),
            len,
        })
    }

    /// Bytes the index occupies at the end of the scratch.
    pub(super) fn len(&self) -> usize {
        self.len
    }

    /// Number of entries.
    #[inline]
    pub(super) fn entries(&self) -> usize {
        self.n
    }

    /// Number of process-image candidates, when counted at the build.
    pub(super) fn candidates(&self) -> Option<usize> {
        self.candidates
    }

    /// Position of the entry at `slot` of the sorted order.
    #[inline]
    pub(super) fn position(&self, slot: usize) -> usize {
        by_width!(self.w, elem(self.order, slot)).1
    }

    /// Offset of entry `pos` in the index segment.
    #[inline]
    pub(super) fn offset(&self, pos: usize) -> usize {
        by_width!(self.w, get(self.offsets, pos))
    }

    /// Key (index << 8 | subindex) of the entry at `slot`.
    #[inline]
    pub(super) fn key_at(&self, slot: usize) -> u32 {
        by_width!(self.w, elem_key(self.order, slot))
    }

    /// Flags of entry `pos`.
    #[inline]
    pub(super) fn flags(&self, pos: usize) -> u8 {
        self.flags.get(pos).copied().unwrap_or(0)
    }

    /// Address word of entry `pos`: `None` without address segment, for
    /// an entry that is no candidate, or [`NOT_PLACED`].
    #[inline]
    pub(super) fn word(&self, pos: usize) -> Option<u16> {
        match self.words.get(pos * 2..pos * 2 + 2) {
            Some(&[a, b]) => Some(u16::from_ne_bytes([a, b])).filter(|w| *w != NOT_PLACED),
            _ => None,
        }
    }

    /// First slot whose key is not below `key` (`entries()` when none).
    #[inline]
    pub(super) fn lower_bound(&self, key: u32) -> usize {
        by_width!(self.w, lower_bound(self.order, self.n, key))
    }
}
