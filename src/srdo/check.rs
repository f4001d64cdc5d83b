//! The SRDO configuration check (`SrdoCheckConfig`, `CcmCheckSrdoConfig`;
//! SAFETY_BEHAVIOUR.md section 2).
//!
//! Every SRDO is checked in ascending order of its communication index,
//! including SRDOs with direction 0 for the first two steps. Per SRDO the
//! steps and their codes are:
//!
//! 1. CRC over the parameters equals 0x13FF sub n: `kCopSrdoCfgCrcError`;
//! 2. direction 0, 1 or 2 and transmission type 254: `kCopSrdoInvalidCfg`;
//!
//! and for active SRDOs (direction 1 or 2) only:
//!
//! 3. refresh time / SCT > 0, SRVT > 0 and, for a receive SRDO,
//!    SRVT ≤ SCT (a pair cannot take longer than the cycle it belongs to):
//!    `kCopSrdoCfgTimingError`;
//! 4. COB-ID 1 odd in 0x101..=0x17F, COB-ID 2 = COB-ID 1 + 1, bits 31..11
//!    zero: `kCopSrdoCfgIdError`; a COB-ID already used by an active SRDO
//!    with a lower index: `kCopSrdoCanIdAlreadyInUse` (no other service of
//!    this stack uses ids in 0x101..0x180);
//! 5. mapping: at least one pair, an even count, no more entries than
//!    `SRDO_MAX_MAPPENTRIES`, normal and inverted entry of each pair of
//!    equal length, every object present, numeric, mappable, of exactly the
//!    mapped length, readable for a transmit SRDO and writable for a receive
//!    SRDO, with a variable behind it (dummy entries 0x0001..0x0007 only for
//!    receive SRDOs with `SRDO_USE_DUMMY_MAPPING`); with static mapping the
//!    variable fields must have been defined: `kCopSrdoErrorMapp`;
//! 6. normal data at most 8 bytes: `kCopSrdoLengthExceeded`;
//! 7. every entry a multiple of `SRDO_GRANULARITY` bits:
//!    `kCopSrdoGranularityMismatch`.
//!
//! The first failing step of the first failing SRDO is reported together
//! with that SRDO's communication index.

use super::{
    COMMU_BASE, CRC_INDEX, Direction, MAPP_OFFSET, MappingEntry, Srdo, TRANSMISSION_TYPE,
    commu_index_of, crc, read_u8, read_u16, read_u32,
};
use crate::config::{SRDO_GRANULARITY, SRDO_MAX_MAPPENTRIES, SRDO_USE_DUMMY_MAPPING};
use crate::error::{CopKernel, OdError, SdoAbort};
use crate::od::ObjectDictionary;
use crate::wire::srdo::{COB_ID_COUNT, COB_ID_MIN, MAX_DATA, SrdoCobIds};

/// The parameters of one SRDO as read from the dictionary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Params {
    pub direction: u8,
    pub sct_ms: u16,
    pub srvt_ms: u8,
    pub cob1: u32,
    pub cob2: u32,
}

impl Params {
    /// Reads 0x1301+n sub 1, 2, 3, 5, 6.
    pub(crate) fn read(od: &ObjectDictionary, commu_index: u16) -> Result<Params, CopKernel> {
        let missing = CopKernel::SrdoNotExist;
        Ok(Params {
            direction: read_u8(od, commu_index, 1).ok_or(missing)?,
            sct_ms: read_u16(od, commu_index, 2).ok_or(missing)?,
            srvt_ms: read_u8(od, commu_index, 3).ok_or(missing)?,
            cob1: read_u32(od, commu_index, 5).ok_or(missing)?,
            cob2: read_u32(od, commu_index, 6).ok_or(missing)?,
        })
    }
}

/// Why a mapping does not hold: the check's kernel code and, for a write
/// that would make it so, the CiA 301 abort code naming the reason
/// (CiA 301 table 22).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MapFault {
    /// The mapped index does not exist: 0x06020000.
    NoObject,
    /// The mapped subindex does not exist: 0x06090011.
    NoSubindex,
    /// Not mappable, wrong access for the direction, not of the mapped
    /// length, no variable, or a dummy entry where none is allowed:
    /// 0x06040041.
    NotMappable,
    /// An odd count or a pair of unequal length: 0x06040043.
    Pairing,
    /// More entries than an SRDO holds: 0x06040042.
    Count,
    /// More than 8 bytes of normal data (`kCopSrdoLengthExceeded`):
    /// 0x06040042.
    Length,
    /// An entry that is not a multiple of the granularity
    /// (`kCopSrdoGranularityMismatch`): 0x06040043.
    Granularity,
}

impl MapFault {
    /// The `tCopKernel` code (that of the configuration check).
    pub(crate) fn kernel(self) -> CopKernel {
        match self {
            MapFault::Length => CopKernel::SrdoLengthExceeded,
            MapFault::Granularity => CopKernel::SrdoGranularityMismatch,
            _ => CopKernel::SrdoErrorMapp,
        }
    }

    /// The kernel code with the SDO abort code of a refused write.
    pub(crate) fn refusal(self) -> OdError {
        let abort = match self {
            MapFault::NoObject => SdoAbort::ObjectNotExist,
            MapFault::NoSubindex => SdoAbort::SubindexNotExist,
            MapFault::NotMappable => SdoAbort::NotMappable,
            MapFault::Pairing | MapFault::Granularity => SdoAbort::ParamIncompatible,
            MapFault::Count | MapFault::Length => SdoAbort::PdoLengthExceeded,
        };
        OdError::new(self.kernel(), abort)
    }
}

/// Checks the object one mapping entry names (or the dummy entry).
/// `Direction::Off` accepts an object that fits either direction.
fn check_object(
    od: &ObjectDictionary,
    entry: MappingEntry,
    direction: Direction,
) -> Result<(), MapFault> {
    let bad = MapFault::NotMappable;
    if let Some(bits) = entry.dummy_bits() {
        // CiA 301 dummy entries: the data type entries 0x0001..0x0007, sub 0,
        // mapped with the size of their type; receive side only.
        return if SRDO_USE_DUMMY_MAPPING
            && direction != Direction::Transmit
            && entry.sub == 0
            && bits == entry.bits
        {
            Ok(())
        } else {
            Err(bad)
        };
    }
    let obj = od.find(entry.index, entry.sub).map_err(|e| {
        if e == OdError::INDEX {
            MapFault::NoObject
        } else {
            MapFault::NoSubindex
        }
    })?;
    let typ = obj.data_type();
    let wire = match typ.encoding() {
        crate::od::Encoding::Numeric { wire, .. } => wire,
        _ => return Err(bad),
    };
    let access = obj.access();
    if !access.mappable() || usize::from(entry.bits) != wire * 8 {
        return Err(bad);
    }
    let access_ok = match direction {
        Direction::Transmit => access.readable(),
        Direction::Receive => access.writable(),
        Direction::Off => access.readable() || access.writable(),
    };
    if !access_ok {
        return Err(bad);
    }
    // The variable must exist now (USERDEF variables are attached by the
    // application before the configuration is declared valid).
    let size = obj.native_size().map_err(|_| bad)?;
    if !matches!(size, 1 | 2 | 4 | 8) || size < wire {
        return Err(bad);
    }
    Ok(())
}

/// Checks the first `count` entries of an SRDO's mapping for `direction`;
/// returns the normal data length in bytes. A count of 0 passes here (the
/// configuration check refuses it for an active SRDO).
fn check_entries(
    od: &ObjectDictionary,
    mapp_index: u16,
    count: u8,
    direction: Direction,
    granularity: u8,
) -> Result<u8, MapFault> {
    if usize::from(count) > SRDO_MAX_MAPPENTRIES {
        return Err(MapFault::Count);
    }
    if count % 2 != 0 {
        return Err(MapFault::Pairing);
    }
    // An empty entry (0) inside the count maps nothing: not mappable.
    let entry = |sub: u8| match read_u32(od, mapp_index, sub) {
        Some(0) => Err(MapFault::NotMappable),
        Some(raw) => Ok(MappingEntry::decode(raw)),
        None => Err(MapFault::Count),
    };
    let mut normal_bits = 0u32;
    let mut granular = true;
    for pair in 0..count / 2 {
        let sub = 2 * pair + 1;
        let normal = entry(sub)?;
        let inverted = entry(sub + 1)?;
        check_object(od, normal, direction)?;
        check_object(od, inverted, direction)?;
        if normal.bits != inverted.bits || normal.bits == 0 {
            return Err(MapFault::Pairing);
        }
        normal_bits += u32::from(normal.bits);
        granular &= u32::from(normal.bits) % u32::from(granularity.max(1)) == 0;
    }
    if normal_bits > 8 * MAX_DATA as u32 {
        return Err(MapFault::Length);
    }
    if !granular {
        return Err(MapFault::Granularity);
    }
    Ok((normal_bits / 8) as u8)
}

/// Checks the mapping of an active SRDO; returns the normal data length.
pub(super) fn check_mapping(
    od: &ObjectDictionary,
    commu_index: u16,
    direction: Direction,
    granularity: u8,
) -> Result<u8, CopKernel> {
    let mapp_index = commu_index + MAPP_OFFSET;
    let count = read_u8(od, mapp_index, 0).ok_or(CopKernel::SrdoErrorMapp)?;
    if count == 0 {
        return Err(CopKernel::SrdoErrorMapp);
    }
    check_entries(od, mapp_index, count, direction, granularity).map_err(MapFault::kernel)
}

/// The check of one write to the mapping of the SRDO `commu_index` while
/// its direction is 0 (manual 2.5: the mapping is checked at each change).
/// Sub 0 := n checks the n entries it enables as the configuration check
/// does; an entry (sub 1..) is checked on its own, since the normal and
/// inverted entries of a pair are written one after the other (0 empties
/// it). The direction the objects' access must fit is the one the
/// dictionary declares for the SRDO (the default of sub 1); an SRDO
/// declared with direction 0 accepts objects of either direction, and the
/// configuration check at 0xA5 judges the direction in force.
pub(crate) fn mapping_write(
    od: &ObjectDictionary,
    commu_index: u16,
    sub: u8,
    v: u64,
    granularity: u8,
) -> Result<(), OdError> {
    let direction = declared_direction(od, commu_index);
    let mapp_index = commu_index + MAPP_OFFSET;
    if sub == 0 {
        let present = od
            .find_entry(mapp_index)
            .map_or(0, |e| od.sub_count(e).saturating_sub(1));
        let count = u8::try_from(v)
            .ok()
            .filter(|n| usize::from(*n) <= present)
            .ok_or(MapFault::Count.refusal())?;
        return check_entries(od, mapp_index, count, direction, granularity)
            .map(|_| ())
            .map_err(MapFault::refusal);
    }
    if v == 0 {
        return Ok(());
    }
    let entry = MappingEntry::decode(v as u32);
    check_object(od, entry, direction).map_err(MapFault::refusal)?;
    if u32::from(entry.bits) % u32::from(granularity.max(1)) != 0 {
        return Err(MapFault::Granularity.refusal());
    }
    Ok(())
}

/// The direction `OBD_CREATE_SRDO_COMMU` gave the SRDO (the default of sub
/// 1); `Direction::Off` when it has none or declares 0.
fn declared_direction(od: &ObjectDictionary, commu_index: u16) -> Direction {
    od.find(commu_index, 1)
        .ok()
        .and_then(|o| o.desc().default_value())
        .and_then(|d| d.first().copied())
        .and_then(Direction::from_u8)
        .unwrap_or(Direction::Off)
}

impl Srdo {
    /// `CcmCheckSrdoConfig`: checks every SRDO (module docs for the steps
    /// and codes). `Err((code, commu_index))` names the first bad SRDO.
    /// Reads the dictionary only; nothing changes.
    pub fn check_config(&self, od: &ObjectDictionary) -> Result<(), (CopKernel, u16)> {
        self.check_config_with(od, SRDO_GRANULARITY)
    }

    /// [`Srdo::check_config`] with the granularity as a parameter (so every
    /// granularity is testable in one build).
    pub(crate) fn check_config_with(
        &self,
        od: &ObjectDictionary,
        granularity: u8,
    ) -> Result<(), (CopKernel, u16)> {
        // Which active SRDO uses each COB-ID pair (duplicate detection).
        let mut used = [false; COB_ID_COUNT / 2];
        for slot in 0..self.count() {
            let Some(commu_index) = commu_index_of(&self.slots, slot) else {
                continue;
            };
            self.check_one(od, slot, commu_index, granularity, &mut used)
                .map_err(|code| (code, commu_index))?;
        }
        Ok(())
    }

    fn check_one(
        &self,
        od: &ObjectDictionary,
        slot: usize,
        commu_index: u16,
        granularity: u8,
        used: &mut [bool; COB_ID_COUNT / 2],
    ) -> Result<(), CopKernel> {
        let number = (commu_index - COMMU_BASE) as u8;
        let stored = read_u16(od, CRC_INDEX, number).ok_or(CopKernel::SrdoCfgCrcError)?;
        if crc::calc(od, commu_index)? != stored {
            return Err(CopKernel::SrdoCfgCrcError);
        }
        let p = Params::read(od, commu_index)?;
        let direction = Direction::from_u8(p.direction).ok_or(CopKernel::SrdoInvalidCfg)?;
        // The transmission type is a constant 254 in every dictionary this
        // library builds; a C dictionary that declared it writable is held
        // to the same value.
        if read_u8(od, commu_index, 4).is_some_and(|t| t != TRANSMISSION_TYPE) {
            return Err(CopKernel::SrdoInvalidCfg);
        }
        if direction == Direction::Off {
            return Ok(());
        }
        if p.sct_ms == 0
            || p.srvt_ms == 0
            || (direction == Direction::Receive && u16::from(p.srvt_ms) > p.sct_ms)
        {
            return Err(CopKernel::SrdoCfgTimingError);
        }
        let ids = SrdoCobIds::new(p.cob1, p.cob2).map_err(|_| CopKernel::SrdoCfgIdError)?;
        let pair = usize::from((ids.normal() - COB_ID_MIN) / 2);
        match used.get_mut(pair) {
            Some(true) => return Err(CopKernel::SrdoCanIdAlreadyInUse),
            Some(u) => *u = true,
            None => return Err(CopKernel::SrdoCfgIdError),
        }
        check_mapping(od, commu_index, direction, granularity)?;
        self.check_static_fields(slot)?;
        Ok(())
    }

    #[cfg(srdo_static_mapping)]
    fn check_static_fields(&self, slot: usize) -> Result<(), CopKernel> {
        match self.fields.get(slot) {
            Some(Some(_)) => Ok(()),
            _ => Err(CopKernel::SrdoErrorMapp),
        }
    }

    #[cfg(not(srdo_static_mapping))]
    fn check_static_fields(&self, _slot: usize) -> Result<(), CopKernel> {
        Ok(())
    }
}

/// Length in bytes of the normal data of an SRDO's mapping (sum of the
/// normal entries), without any other check. `kCopSrdoErrorMapp` when the
/// mapping cannot be read.
pub(crate) fn mapped_len(od: &ObjectDictionary, commu_index: u16) -> Result<u8, CopKernel> {
    let mapp_index = commu_index + MAPP_OFFSET;
    let bad = CopKernel::SrdoErrorMapp;
    let count = read_u8(od, mapp_index, 0).ok_or(bad)?;
    let mut bits = 0u32;
    for sub in (1..=count).step_by(2) {
        bits += u32::from(MappingEntry::decode(read_u32(od, mapp_index, sub).ok_or(bad)?).bits);
    }
    Ok(u8::try_from(bits.div_ceil(8)).unwrap_or(u8::MAX))
}
