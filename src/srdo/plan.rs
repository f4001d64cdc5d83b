//! Copy plans: how the data of an SRDO move between its two frames and the
//! mapped variables.
//!
//! A plan is built once, when the node enters OPERATIONAL with a valid
//! configuration (the mapping cannot change while OPERATIONAL), so frame
//! processing never searches the dictionary.
//!
//! * Dynamic mapping: one reference to the subindex description of each
//!   mapped object, its array element and its wire length. Variables are
//!   kept in CPU byte order, so each value is converted between the
//!   little-endian frame and the variable (and sign-extended where the
//!   variable is wider than the mapped type).
//! * Static mapping (`SRDO_USE_STATIC_MAPPING`): the two contiguous
//!   variable fields of `CcmStaticDefineSrdoVarFields`; frame bytes are
//!   copied to and from them unchanged (manual 2.6 and 2.8.7).

use core::sync::atomic::{AtomicU8, Ordering};

#[cfg(not(srdo_static_mapping))]
use crate::config::SRDO_MAX_MAPPENTRIES;
#[cfg(not(srdo_static_mapping))]
use crate::od::{Access, DataType, ObdSubEntry, ObjectDictionary, Storage};
use crate::wire::srdo::payload_mask;

#[cfg(not(srdo_static_mapping))]
use super::{MAPP_OFFSET, MappingEntry, read_u8, read_u32};

/// Marks a signed entry in [`Plan::meta`] (low nibble: wire bytes).
#[cfg(not(srdo_static_mapping))]
const META_SIGNED: u8 = 0x80;

/// Where the frame bytes of a [`Plan::Bytes`] beyond the mapped length go
/// (and come from; they are masked off). Nothing reads it.
#[cfg(not(srdo_static_mapping))]
static SINK: AtomicU8 = AtomicU8::new(0);

/// The copy plan of one SRDO with dynamic mapping.
#[cfg(not(srdo_static_mapping))]
#[derive(Clone, Copy, Debug)]
pub(crate) enum Plan {
    /// Every entry is a RAM variable of exactly its mapped length and no
    /// two entries share a byte: each frame byte has one variable byte,
    /// resolved when the plan was built. `normal[k]` / `inverted[k]` is the
    /// variable byte of byte k of frame 1 / frame 2 ([`SINK`] beyond the
    /// mapped length). Writing byte by byte in this order leaves the
    /// variables exactly as [`General::scatter`] does.
    Bytes {
        normal: [&'static AtomicU8; 8],
        inverted: [&'static AtomicU8; 8],
    },
    /// Anything else (variables attached by the application, variables
    /// wider than their mapped type, dummy entries, shared bytes).
    General(General),
}

#[cfg(not(srdo_static_mapping))]
impl Plan {
    /// An empty plan.
    pub(crate) const EMPTY: Plan = Plan::General(General::EMPTY);

    /// Builds the plan of an SRDO whose configuration passed the check.
    /// `None` when an object cannot be resolved (then the SRDO does not run).
    pub(crate) fn build(od: &ObjectDictionary, commu_index: u16) -> Option<Plan> {
        let general = General::build(od, commu_index)?;
        Some(general.bytes().unwrap_or(Plan::General(general)))
    }

    /// Reads the normal and the inverted data from the mapped variables
    /// (frame layout, little-endian). `None` when a variable is missing.
    #[inline]
    pub(crate) fn gather(&self, dlc: u8) -> Option<(u64, u64)> {
        match self {
            Plan::Bytes { normal, inverted } => {
                let mask = payload_mask(dlc);
                Some((
                    load_frame(normal, dlc) & mask,
                    load_frame(inverted, dlc) & mask,
                ))
            }
            Plan::General(g) => g.gather(),
        }
    }

    /// Writes received normal and inverted data to the mapped variables.
    /// Either every variable is written or, when one is missing, none.
    #[inline(always)]
    pub(crate) fn scatter(&self, normal: u64, inverted: u64, dlc: u8) -> bool {
        match self {
            Plan::Bytes {
                normal: n,
                inverted: i,
            } => {
                store_frame(n, normal, dlc);
                store_frame(i, inverted, dlc);
                true
            }
            Plan::General(g) => g.scatter(normal, inverted),
        }
    }
}

/// The frame bytes from their variable bytes (little-endian); bytes 4..8
/// only when they are mapped (`dlc` above 4), else 0.
#[cfg(not(srdo_static_mapping))]
#[inline(always)]
fn load_frame(bytes: &[&'static AtomicU8; 8], dlc: u8) -> u64 {
    let [b0, b1, b2, b3, b4, b5, b6, b7] = bytes;
    let low = u32::from_le_bytes([
        b0.load(Ordering::Relaxed),
        b1.load(Ordering::Relaxed),
        b2.load(Ordering::Relaxed),
        b3.load(Ordering::Relaxed),
    ]);
    let high = if dlc > 4 {
        u32::from_le_bytes([
            b4.load(Ordering::Relaxed),
            b5.load(Ordering::Relaxed),
            b6.load(Ordering::Relaxed),
            b7.load(Ordering::Relaxed),
        ])
    } else {
        0
    };
    u64::from(low) | u64::from(high) << 32
}

/// The eight frame bytes into their variable bytes.
#[cfg(not(srdo_static_mapping))]
#[inline(always)]
fn store_frame(bytes: &[&'static AtomicU8; 8], v: u64, dlc: u8) {
    let [b0, b1, b2, b3, b4, b5, b6, b7] = bytes;
    let [v0, v1, v2, v3, v4, v5, v6, v7] = v.to_le_bytes();
    // Bytes 4..8 only when they are mapped (else they all go to SINK).
    if dlc > 4 {
        b4.store(v4, Ordering::Relaxed);
        b5.store(v5, Ordering::Relaxed);
        b6.store(v6, Ordering::Relaxed);
        b7.store(v7, Ordering::Relaxed);
    }
    b0.store(v0, Ordering::Relaxed);
    b1.store(v1, Ordering::Relaxed);
    b2.store(v2, Ordering::Relaxed);
    b3.store(v3, Ordering::Relaxed);
}

/// The description a dummy entry (and an unused entry) of a [`General`]
/// plan points to; nothing else does.
#[cfg(not(srdo_static_mapping))]
static NO_OBJECT: ObdSubEntry = ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[0]);

/// True for [`NO_OBJECT`].
#[cfg(not(srdo_static_mapping))]
fn is_dummy(desc: &ObdSubEntry) -> bool {
    core::ptr::eq(desc, &NO_OBJECT)
}

/// The general copy plan: the subindex of each entry, resolved to its
/// variable on every transfer.
#[cfg(not(srdo_static_mapping))]
#[derive(Clone, Copy, Debug)]
pub(crate) struct General {
    /// Subindex description of each entry in mapping order (normal,
    /// inverted, normal, ...); [`NO_OBJECT`] for a dummy entry (a reference
    /// that is never null leaves [`Plan`] a spare value for its variant).
    desc: [&'static ObdSubEntry; SRDO_MAX_MAPPENTRIES],
    /// Array element of each entry (0 for plain subindices).
    element: [u8; SRDO_MAX_MAPPENTRIES],
    /// Wire bytes (low nibble) and [`META_SIGNED`].
    meta: [u8; SRDO_MAX_MAPPENTRIES],
    /// Number of entries.
    count: u8,
}

#[cfg(not(srdo_static_mapping))]
impl General {
    /// An empty plan.
    const EMPTY: General = General {
        desc: [&NO_OBJECT; SRDO_MAX_MAPPENTRIES],
        element: [0; SRDO_MAX_MAPPENTRIES],
        meta: [0; SRDO_MAX_MAPPENTRIES],
        count: 0,
    };

    /// The general plan of an SRDO's mapping; `None` when an object cannot
    /// be resolved.
    pub(super) fn build(od: &ObjectDictionary, commu_index: u16) -> Option<General> {
        let mapp_index = commu_index + MAPP_OFFSET;
        let count = read_u8(od, mapp_index, 0)?;
        let mut plan = General::EMPTY;
        for i in 0..usize::from(count) {
            let sub = u8::try_from(i + 1).ok()?;
            let entry = MappingEntry::decode(read_u32(od, mapp_index, sub)?);
            let wire = entry.bits / 8;
            let (desc, element, signed) = if entry.dummy_bits().is_some() {
                (&NO_OBJECT, 0, false)
            } else {
                let obj = od.find(entry.index, entry.sub).ok()?;
                let element = obj.sub().checked_sub(obj.desc().sub())?;
                (obj.desc(), element, obj.data_type().is_signed())
            };
            *plan.desc.get_mut(i)? = desc;
            *plan.element.get_mut(i)? = element;
            *plan.meta.get_mut(i)? = (wire & 0x0F) | if signed { META_SIGNED } else { 0 };
        }
        plan.count = count;
        Some(plan)
    }

    /// Resolves the variable of every entry. `None` when a variable has
    /// gone (a USERDEF variable detached while OPERATIONAL).
    #[inline]
    fn resolve(&self) -> Option<[Option<&'static [AtomicU8]>; SRDO_MAX_MAPPENTRIES]> {
        let mut vars = [None; SRDO_MAX_MAPPENTRIES];
        for ((v, desc), element) in vars
            .iter_mut()
            .zip(&self.desc)
            .zip(&self.element)
            .take(usize::from(self.count))
        {
            if !is_dummy(desc) {
                let d = *desc;
                *v = Some(match d.storage(usize::from(*element))? {
                    Storage::Ram(m) => m,
                    Storage::Var(e) => e.data()?,
                    _ => return None,
                });
            }
        }
        Some(vars)
    }

    /// The byte plan of this mapping, when every entry is a RAM variable
    /// of exactly its mapped length, no byte is mapped twice and the data
    /// fit one frame.
    fn bytes(&self) -> Option<Plan> {
        let sink: &'static AtomicU8 = &SINK;
        let mut frames = [[sink; 8]; 2];
        let mut offset = 0usize;
        for i in 0..usize::from(self.count) {
            let wire = usize::from(*self.meta.get(i)? & 0x0F);
            let element = usize::from(*self.element.get(i)?);
            // Dummy entries and attached variables are not bytes of RAM.
            let desc = *self.desc.get(i)?;
            if is_dummy(desc) {
                return None;
            }
            let var = desc.ram_var(element)?;
            if var.len() != wire {
                return None;
            }
            for k in 0..wire {
                // Frame byte k is the k-th least significant byte.
                let byte = var.get(cpu_byte(k, wire, LITTLE))?;
                // A byte written by two entries would depend on their order.
                if frames.iter().flatten().any(|b| core::ptr::eq(*b, byte)) {
                    return None;
                }
                *frames.get_mut(i % 2)?.get_mut(offset + k)? = byte;
            }
            if i % 2 == 1 {
                offset += wire;
            }
        }
        let [normal, inverted] = frames;
        Some(Plan::Bytes { normal, inverted })
    }

    /// Reads the normal and the inverted data from the mapped variables
    /// (frame layout, little-endian). `None` when a variable is missing.
    pub(super) fn gather(&self) -> Option<(u64, u64)> {
        let vars = self.resolve()?;
        let mut data = [0u64; 2];
        self.each_entry(&vars, |frame, var, meta, offset| {
            let value = var.map_or(0, load_native) & payload_mask(meta & 0x0F);
            if let Some(d) = data.get_mut(frame) {
                *d |= value.checked_shl(offset).unwrap_or(0);
            }
        });
        let [normal, inverted] = data;
        Some((normal, inverted))
    }

    /// Calls `f(frame, variable, meta, bit offset)` for each mapped entry in
    /// mapping order: frame 0 (normal data) and 1 (inverted data)
    /// alternate, and each pair starts where the previous one ended.
    #[inline(always)]
    fn each_entry(
        &self,
        vars: &[Option<&'static [AtomicU8]>; SRDO_MAX_MAPPENTRIES],
        mut f: impl FnMut(usize, Option<&'static [AtomicU8]>, u8, u32),
    ) {
        let mut offset = 0u32;
        for (i, (var, meta)) in vars
            .iter()
            .zip(&self.meta)
            .take(usize::from(self.count))
            .enumerate()
        {
            f(i % 2, *var, *meta, offset);
            if i % 2 == 1 {
                offset += 8 * u32::from(*meta & 0x0F);
            }
        }
    }

    /// Writes received normal and inverted data to the mapped variables.
    /// Either every variable is written or, when one is missing, none.
    #[inline(never)]
    pub(super) fn scatter(&self, normal: u64, inverted: u64) -> bool {
        let Some(vars) = self.resolve() else {
            return false;
        };
        let data = [normal, inverted];
        self.each_entry(&vars, |frame, var, meta, offset| {
            let wire = meta & 0x0F;
            if let (Some(m), Some(d)) = (var, data.get(frame)) {
                let mut value = d.checked_shr(offset).unwrap_or(0) & payload_mask(wire);
                if meta & META_SIGNED != 0 {
                    value = crate::od::value::sign_extend(value, usize::from(wire));
                }
                store_native(m, value);
            }
        });
        true
    }
}

/// The byte order of the CPU the library is built for.
#[cfg(not(srdo_static_mapping))]
const LITTLE: bool = cfg!(target_endian = "little");

/// Where byte `k` of significance (0: the least significant) of an
/// `n`-byte value stands in memory, in little-endian (`little`) or
/// big-endian byte order; its own inverse. A parameter, not the build's
/// byte order, so that both orders are tested on every host; with the
/// constant [`LITTLE`] it folds away.
#[cfg(not(srdo_static_mapping))]
#[inline(always)]
pub(super) const fn cpu_byte(k: usize, n: usize, little: bool) -> usize {
    if little { k } else { n - 1 - k }
}

/// Reads a variable of 1, 2, 4 or 8 bytes in CPU byte order as an integer.
#[cfg(not(srdo_static_mapping))]
#[inline]
fn load_native(m: &[AtomicU8]) -> u64 {
    let n = m.len();
    let mut v = 0u64;
    for (i, b) in m.iter().enumerate() {
        let pos = cpu_byte(i, n, LITTLE);
        v |= u64::from(b.load(Ordering::Relaxed))
            .checked_shl(8 * pos as u32)
            .unwrap_or(0);
    }
    v
}

/// Writes an integer into a variable of 1, 2, 4 or 8 bytes in CPU order.
#[cfg(not(srdo_static_mapping))]
#[inline]
fn store_native(m: &[AtomicU8], v: u64) {
    let n = m.len();
    for (i, b) in m.iter().enumerate() {
        let pos = cpu_byte(i, n, LITTLE);
        b.store(
            v.checked_shr(8 * pos as u32).unwrap_or(0) as u8,
            Ordering::Relaxed,
        );
    }
}

/// The variable fields of one SRDO with static mapping: `len` bytes of
/// normal and of inverted data, in frame order.
#[cfg(srdo_static_mapping)]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fields {
    pub normal: &'static [AtomicU8],
    pub inverted: &'static [AtomicU8],
}

#[cfg(srdo_static_mapping)]
impl Fields {
    /// The two fields as frame data (little-endian `u64`).
    pub(crate) fn gather(&self) -> Option<(u64, u64)> {
        Some((load_bytes(self.normal), load_bytes(self.inverted)))
    }

    /// Copies received frame data into the two fields.
    pub(crate) fn scatter(&self, normal: u64, inverted: u64) -> bool {
        store_bytes(self.normal, normal);
        store_bytes(self.inverted, inverted);
        true
    }
}

/// Frame bytes from a field, unchanged (byte 0 of the field is byte 0 of
/// the frame).
#[cfg(srdo_static_mapping)]
#[inline]
fn load_bytes(field: &[AtomicU8]) -> u64 {
    let mut v = 0u64;
    for (i, b) in field.iter().take(8).enumerate() {
        v |= u64::from(b.load(Ordering::Relaxed)) << (8 * i as u32);
    }
    v & payload_mask(field.len() as u8)
}

/// Frame bytes into a field, unchanged.
#[cfg(srdo_static_mapping)]
#[inline]
fn store_bytes(field: &[AtomicU8], v: u64) {
    for (i, b) in field.iter().take(8).enumerate() {
        b.store((v >> (8 * i as u32)) as u8, Ordering::Relaxed);
    }
}

/// Checks that every mapped object of an SRDO (static mapping) is the
/// variable at its byte offset in the normal or inverted field: same start
/// address, same size. Dummy entries have no variable and are skipped.
#[cfg(srdo_static_mapping)]
pub(crate) fn match_fields(
    od: &crate::od::ObjectDictionary,
    commu_index: u16,
    normal: &'static [AtomicU8],
    inverted: &'static [AtomicU8],
) -> Result<(), crate::error::CopKernel> {
    use super::{MAPP_OFFSET, MappingEntry, read_u8, read_u32};
    use crate::config::SRDO_MAX_MAPPENTRIES;
    use crate::error::CopKernel;
    use crate::od::Storage;
    let bad = CopKernel::SrdoErrorMapp;
    let mapp_index = commu_index + MAPP_OFFSET;
    let count = read_u8(od, mapp_index, 0).ok_or(bad)?;
    if count % 2 != 0 || usize::from(count) > SRDO_MAX_MAPPENTRIES {
        return Err(bad);
    }
    let mut offset = 0usize;
    for sub in 1..=count {
        let e = MappingEntry::decode(read_u32(od, mapp_index, sub).ok_or(bad)?);
        if e.bits % 8 != 0 {
            return Err(bad);
        }
        let len = usize::from(e.bits / 8);
        if e.dummy_bits().is_none() {
            let field = if sub % 2 == 1 { normal } else { inverted };
            let var = match od.find(e.index, e.sub).and_then(|o| o.storage()) {
                Ok(Storage::Ram(m)) => m,
                Ok(Storage::Var(v)) => v.data().ok_or(bad)?,
                _ => return Err(bad),
            };
            let expected = field.get(offset..offset + len).ok_or(bad)?;
            if var.len() != len || !core::ptr::eq(var.as_ptr(), expected.as_ptr()) {
                return Err(bad);
            }
        }
        if sub % 2 == 0 {
            offset += len;
        }
    }
    Ok(())
}
