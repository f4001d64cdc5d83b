//! From the parsed file to the container, the checks every container gets
//! before it is written (ours, or another tool's with `--verify`), and the
//! pool a container needs.

use std::collections::BTreeMap;
use std::mem::{align_of, size_of};

use cop::CopKernel;
use cop::od::dcf::{
    self, Container, EntrySpec, NOT_PLACED, PiLayout, PiParams, attr, index_scratch_len,
};
use cop::od::dynamic::Plan;
use cop::od::{ObdEntry, ObdSubEntry, ObjectDictionary};
use cop::pdo::Direction;

use crate::{Dcf, Error};

impl Dcf {
    /// The process-image layout of the network variables (seed chapter 6).
    pub fn layout(&self) -> PiLayout {
        let mut l = PiLayout::default();
        for o in &self.objects {
            l.add(o.index, o.sub);
        }
        l
    }

    /// The entries of the index segment with their attributes.
    pub fn entries(&self) -> Vec<EntrySpec<'_>> {
        self.objects
            .iter()
            .map(|o| EntrySpec {
                index: o.index,
                sub: o.sub,
                data: &o.data,
                attr: o.attr,
            })
            .collect()
    }

    /// The address words, one per candidate (`cop::od::dcf::is_pi_candidate`).
    pub fn addresses(&self) -> Vec<u16> {
        let layout = self.layout();
        let mut subs: BTreeMap<u16, usize> = BTreeMap::new();
        for o in &self.objects {
            *subs.entry(o.index).or_default() += 1;
        }
        self.objects
            .iter()
            .filter(|o| dcf::is_pi_candidate(o.index, o.sub, subs.get(&o.index) > Some(&1)))
            .map(|o| match layout.place(o.index, o.sub) {
                Some((off, _)) => u16::try_from(off).unwrap_or(NOT_PLACED),
                None => NOT_PLACED,
            })
            .collect()
    }

    /// The process-image parameters, when there are network variables.
    pub fn pi_params(&self) -> Option<PiParams> {
        self.objects
            .iter()
            .any(|o| dcf::rule_offset(o.index, o.sub).is_some())
            .then(|| self.layout().params())
    }

    /// The binary container (all five segments where they have content),
    /// checked with [`verify`] before it is handed out.
    pub fn container(&self) -> Result<Vec<u8>, Error> {
        let entries = self.entries();
        let addresses = self.addresses();
        let addr = (!addresses.is_empty()).then_some(addresses.as_slice());
        let pi = self.pi_params();
        let whole = |msg: String| Error::whole(&self.file, msg);
        let n = dcf::encoded_len(&entries, addr, true, pi.as_ref())
            .ok_or_else(|| whole("container larger than 4 GiB".into()))?;
        let mut out = vec![0u8; n];
        dcf::encode(&entries, addr, true, pi.as_ref(), &mut out)
            .map_err(|e| whole(format!("{e:?}")))?;
        let v = verify(&out).map_err(|e| whole(format!("container does not verify: {e}")))?;
        if let Some((i, s, _)) = v.repeated.first() {
            return Err(whole(format!("0x{i:04X} sub {s} written twice")));
        }
        Ok(out)
    }
}

/// What [`verify`] found in a container.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Verified {
    /// Entries of the index segment.
    pub entries: usize,
    /// Variables the address segment places in the process image.
    pub placed: usize,
    /// Subindices written more than once, with the number of writes.
    pub repeated: Vec<(u16, u8, usize)>,
    /// The process image `DynBuildOd` reports (parameter segment, else
    /// the layout of the offset rule), when the container has network
    /// variables or a parameter segment.
    pub pi: Option<PiParams>,
}

/// The bytes a variable of entry `e` takes in the process image, as
/// `DynBuildOd` places it (`cop::od::dynamic`): network variables the C
/// width of their seed table 2 type, BOOLEAN 1, NUMERIC the C width of
/// UNSIGNEDn of the entry's size; strings and domains stay in the pool.
fn placed_size(e: &dcf::Entry<'_>) -> Option<usize> {
    if let Some(nv) = dcf::network_variable(e.index) {
        return Some(dcf::element_size(nv.typ));
    }
    match e.attr.map(|a| a & attr::TYPE_MASK) {
        Some(attr::BOOLEAN) => Some(1),
        Some(attr::NUMERIC) => Some(match e.data.len() {
            n @ (1 | 2) => n,
            3 | 4 => 4,
            _ => 8,
        }),
        _ => None,
    }
}

/// Checks a container beyond what `DynBuildOd` refuses today
/// (`Container::parse`): the process image the container reports covers
/// every byte the address segment gives its variables, inside the window
/// of their direction (inputs 0xA000–0xA47F, outputs 0xA480–0xA8FF), and
/// no two variables share bytes.
///
/// A subindex written twice is no error: a CiA 302 concise DCF is a
/// sequence of writes (a configuration tool writes a PDO's COB-ID invalid,
/// then the mapping, then the COB-ID valid), and `DynBuildOd` gives the
/// same result, the last value of every object and each PDO reconfigured
/// as a unit. They are listed in [`Verified::repeated`]. dcf2bin itself
/// never repeats an entry (a DCF that describes a subindex twice is
/// refused).
pub fn verify(bytes: &[u8]) -> Result<Verified, String> {
    let c = Container::parse(bytes).map_err(|e| format!("{e:?} (kCopDynInvalidConfig)"))?;
    let mut seen: BTreeMap<(u16, u8), usize> = BTreeMap::new();
    for e in c.entries() {
        *seen.entry((e.index, e.sub)).or_default() += 1;
    }
    let repeated = seen
        .into_iter()
        .filter(|(_, n)| *n > 1)
        .map(|((i, s), n)| (i, s, n))
        .collect();
    let mut layout = PiLayout::default();
    for e in c.entries_in(dcf::NETVAR_INPUT_BASE, 0xA8FF) {
        layout.add(e.index, e.sub);
    }
    let has_netvars = c
        .entries_in(dcf::NETVAR_INPUT_BASE, 0xA8FF)
        .next()
        .is_some();
    let pi = c
        .pi_params()
        .or_else(|| has_netvars.then(|| layout.params()));
    let mut placed = 0;
    if let (true, Some(pi)) = (c.has_addresses(), pi) {
        let mut spans: Vec<(u32, u32, u16, u8)> = Vec::new();
        for (e, word) in c.addressed() {
            let (Some(w), Some(size)) = (word, placed_size(&e)) else {
                continue;
            };
            let (at, end) = (u32::from(w), u32::from(w) + size as u32);
            let what = format!(
                "0x{:04X} sub {} at offset {at} ({size} bytes)",
                e.index, e.sub
            );
            if end > pi.total {
                return Err(format!(
                    "{what} ends after the process image of {} bytes the parameter segment reports",
                    pi.total
                ));
            }
            // As DynBuildOd: inside the input or the output area, whichever
            // (tools differ in which area they give RPDO and TPDO data).
            if !pi.covers(at, size) {
                return Err(format!(
                    "{what} lies in neither the input area {}..{} nor the output area {}..{} the parameter segment reports",
                    pi.input_offset,
                    pi.input_offset + pi.input_size,
                    pi.output_offset,
                    pi.output_offset + pi.output_size
                ));
            }
            spans.push((at, end, e.index, e.sub));
            placed += 1;
        }
        spans.sort_unstable();
        for w in spans.windows(2) {
            if let [a, b] = w {
                if b.0 < a.1 {
                    return Err(format!(
                        "0x{:04X} sub {} and 0x{:04X} sub {} share bytes of the process image",
                        a.2, a.3, b.2, b.3
                    ));
                }
            }
        }
    }
    Ok(Verified {
        entries: c.len(),
        placed,
        repeated,
        pi,
    })
}

/// The pool (`OBD_DYNAMIC_POOL_SIZE`) one build of a container takes,
/// following the regions of `cop::ffi::dynod` (index table, subindex
/// tables, variables outside the image, undo snapshot, copy of the index
/// segment).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PoolNeed {
    /// Objects the build creates.
    pub new_indices: usize,
    /// Subindices it creates.
    pub new_subs: usize,
    /// Entries of the application's user part, merged into the new table.
    pub user_entries: usize,
    /// Bytes of the variables that are not in the process image.
    pub data_bytes: usize,
    /// Bytes of the snapshot of existing values the build overwrites.
    pub snapshot_bytes: usize,
    /// Bytes of the kept copy of the index segment.
    pub copy_bytes: usize,
    /// Build-time index and notes (linear build; without room for them
    /// the build is quadratic, same result).
    pub scratch_bytes: usize,
    /// PDO channels the build takes from the pool on this build of the
    /// library (its `PDO_MAX_RXPDO_IN_OBD` / `PDO_MAX_TXPDO_IN_OBD` 0).
    pub pooled_channels: PerDirection,
    /// PDO channels the container needs from the pool on a node whose
    /// obdcfg.h counts 0 RPDOs and 0 TPDOs: highest RPDO number + 1 and
    /// highest TPDO number + 1 of its entries.
    pub container_channels: PerDirection,
    /// Bytes of one RPDO and of one TPDO channel on this host
    /// (`cop::pdo::channel_size`; a TPDO's holds its change watch); on
    /// 32-bit targets they are smaller (narrower pointers), so figures
    /// with them are upper bounds there.
    pub channel_bytes: PerDirection,
}

/// A figure for each PDO direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PerDirection {
    /// Receive PDOs.
    pub rx: usize,
    /// Transmit PDOs.
    pub tx: usize,
}

impl PerDirection {
    /// Both directions together.
    pub fn total(&self) -> usize {
        self.rx + self.tx
    }
}

/// Alignment of the PDO channels in the pool (at most 8); the TPDO
/// channels follow the RPDO ones, whose size is a multiple of it.
const CHANNEL_ALIGN: usize = 8;

impl PoolNeed {
    fn end(&self, entry: usize, sub: usize, sub_align: usize) -> usize {
        self.end_with(entry, sub, sub_align, self.pooled_channels)
    }

    fn end_with(
        &self,
        entry: usize,
        sub: usize,
        sub_align: usize,
        channels: PerDirection,
    ) -> usize {
        let tables = (self.user_entries + self.new_indices) * entry;
        let subs_end = tables.div_ceil(sub_align) * sub_align + self.new_subs * sub;
        let chan_end = if channels.total() == 0 {
            subs_end
        } else {
            subs_end.div_ceil(CHANNEL_ALIGN) * CHANNEL_ALIGN
                + channels.rx * self.channel_bytes.rx
                + channels.tx * self.channel_bytes.tx
        };
        chan_end + self.data_bytes + self.snapshot_bytes + self.copy_bytes
    }

    /// [`PoolNeed::target32`] on a node whose obdcfg.h counts 0 RPDOs and
    /// 0 TPDOs, so that the container's PDOs take their state from the
    /// pool (an upper bound: the channel size is this host's).
    pub fn target32_pdos_from_pool(&self) -> usize {
        self.end_with(16, 16, 4, self.container_channels)
    }

    /// Smallest pool on a 32-bit target (TMS570, Cortex-M/R: `tObdEntry`
    /// and `tObdSubEntry` 16 bytes each, 4-byte alignment).
    pub fn target32(&self) -> usize {
        self.end(16, 16, 4)
    }

    /// The pool on a 32-bit target with room for the build-time index.
    pub fn target32_linear(&self) -> usize {
        let end = self.target32();
        end.max(end - self.copy_bytes + self.scratch_bytes)
    }

    /// Smallest pool on the host this tool runs on.
    pub fn host(&self) -> usize {
        self.end(
            size_of::<ObdEntry>(),
            size_of::<ObdSubEntry>(),
            align_of::<ObdSubEntry>(),
        )
    }
}

/// The pool `bytes` needs on the node whose dictionary (before the build)
/// is `od`, with a process image of `image_len` bytes (0: none, every
/// variable in the pool). Errors are `DynBuildOd`'s for the container.
pub fn pool_need(
    bytes: &[u8],
    od: &ObjectDictionary,
    image_len: usize,
) -> Result<PoolNeed, CopKernel> {
    let c = Container::parse(bytes).map_err(|e| e.kernel())?;
    let plan = Plan::new(c, od, image_len)?;
    let seg = c.index_segment().len();
    let highest = |from: u16, to: u16| {
        c.entries_in(from, to)
            .map(|e| usize::from(e.index - from) % 0x200 + 1)
            .max()
            .unwrap_or(0)
    };
    let rx = highest(0x1400, 0x17FF);
    let tx = highest(0x1800, 0x1BFF);
    Ok(PoolNeed {
        new_indices: plan.new_indices,
        new_subs: plan.new_subs,
        user_entries: od.part(cop::od::Part::User).len(),
        data_bytes: plan.data_bytes,
        snapshot_bytes: plan.snapshot_bytes,
        copy_bytes: seg,
        scratch_bytes: index_scratch_len(c.len(), seg, c.has_addresses()).unwrap_or(usize::MAX)
            + c.len(),
        pooled_channels: PerDirection {
            rx: plan.rx_channels,
            tx: plan.tx_channels,
        },
        container_channels: PerDirection { rx, tx },
        channel_bytes: PerDirection {
            rx: cop::pdo::channel_size(Direction::Rx),
            tx: cop::pdo::channel_size(Direction::Tx),
        },
    })
}

/// [`pool_need`] on a node that has none of the container's objects (every
/// entry creates one; nothing is overwritten).
pub fn pool_need_alone(bytes: &[u8], image_len: usize) -> Result<PoolNeed, CopKernel> {
    let od = ObjectDictionary::new(&[], &[], &[]).map_err(|_| CopKernel::DynInvalidConfig)?;
    pool_need(bytes, &od, image_len)
}
