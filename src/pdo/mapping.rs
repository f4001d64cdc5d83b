//! The rules for PDO parameters (CiA 301 §7.5.2.35–38): which mapping
//! entries are acceptable, and which writes to the communication and
//! mapping objects are allowed in the present state of the PDO. Every rule
//! reads the dictionary, so SDO downloads, `CcmWriteObject` and
//! `CcmDefinePdoTab` are judged alike.

use crate::error::{CopKernel, OdError, SdoAbort};
use crate::od::{DataType, Object, ObjectDictionary, Staged};
use crate::wire::pdo::{self as wire, COB_INVALID, COB_NO_RTR, MAX_BITS, MapEntry, tx_type};

use super::{Direction, PDO_MAX_MAPPENTRIES, PdoIndex, Role};

/// Refusals, each a kernel code for `CcmWriteObject` / `CcmDefinePdoTab`
/// paired with the CiA 301 abort code an SDO client receives.
pub mod refuse {
    use super::*;

    /// The object may not be mapped (not kObdAccPdo, wrong access for the
    /// direction, wrong length, not a fixed-size type): 0x06040041.
    pub const NOT_MAPPABLE: OdError = OdError::new(CopKernel::PdoErrorMapp, SdoAbort::NotMappable);
    /// A length that is not a multiple of 8 bits without bit mapping.
    pub const GRANULARITY: OdError =
        OdError::new(CopKernel::PdoGranularityMismatch, SdoAbort::NotMappable);
    /// More than 64 bits or more entries than the PDO has: 0x06040042.
    pub const LENGTH: OdError =
        OdError::new(CopKernel::PdoLengthExceeded, SdoAbort::PdoLengthExceeded);
    /// The mapped index does not exist: 0x06020000.
    pub const NO_OBJECT: OdError =
        OdError::new(CopKernel::PdoVarNotFound, SdoAbort::ObjectNotExist);
    /// The mapped subindex does not exist: 0x06090011.
    pub const NO_SUBINDEX: OdError =
        OdError::new(CopKernel::PdoVarNotFound, SdoAbort::SubindexNotExist);
    /// A value CiA 301 does not allow here (reserved transmission type,
    /// restricted or malformed COB-ID, COB-ID or inhibit time changed while
    /// the PDO is valid): 0x06090030.
    pub const INVALID: OdError = OdError::VALUE_RANGE;
    /// The mapping changes while the PDO is valid, or an entry changes
    /// while subindex 0 is not 0 (CiA 301 mapping procedure): 0x08000022.
    pub const STATE: OdError = OdError::new(CopKernel::PdoErrorMapp, SdoAbort::DeviceState);
}

/// How strict the mapping rules are (`PDO_USE_BIT_MAPPING`,
/// `PDO_USE_DUMMY_MAPPING`). A value instead of constants so that the unit
/// tests can check both settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rules {
    /// BOOLEANs may be mapped as one bit and objects need not start on a
    /// byte boundary.
    pub bit_mapping: bool,
    /// RPDOs may map data type indices (0x0001..) as place holders.
    pub dummy: bool,
}

/// The rules of this build.
pub const RULES: Rules = Rules {
    bit_mapping: super::PDO_USE_BIT_MAPPING,
    dummy: super::PDO_USE_DUMMY_MAPPING,
};

/// True for a dummy entry: a data type index with subindex 0 (CiA 301
/// §7.5.2.36, "dummy mapping").
pub fn is_dummy(e: MapEntry) -> bool {
    e.index != 0 && e.index < 0x0020 && e.sub == 0
}

fn length_ok(typ: DataType, bits: u8, rules: Rules) -> Result<(), OdError> {
    let wire = typ.wire_size().ok_or(refuse::NOT_MAPPABLE)?;
    if typ == DataType::Bool && bits == 1 {
        return if rules.bit_mapping {
            Ok(())
        } else {
            Err(refuse::GRANULARITY)
        };
    }
    if usize::from(bits) == wire * 8 {
        Ok(())
    } else if bits % 8 != 0 && !rules.bit_mapping {
        Err(refuse::GRANULARITY)
    } else {
        Err(refuse::NOT_MAPPABLE)
    }
}

/// Checks one mapping entry for a PDO of direction `dir`; returns its
/// length in bits. An entry of 0 is not a mapping (callers that allow empty
/// subindices test for 0 first).
pub fn check_entry(
    od: &ObjectDictionary,
    dir: Direction,
    raw: u32,
    rules: Rules,
) -> Result<u8, OdError> {
    let e = MapEntry::decode(raw);
    if u16::from(e.bits) > MAX_BITS {
        return Err(refuse::LENGTH);
    }
    if e.bits == 0 {
        return Err(refuse::NOT_MAPPABLE);
    }
    if is_dummy(e) {
        let typ = DataType::from_code(e.index).ok_or(refuse::NO_OBJECT)?;
        if dir == Direction::Tx || !rules.dummy {
            return Err(refuse::NOT_MAPPABLE);
        }
        length_ok(typ, e.bits, rules)?;
        return Ok(e.bits);
    }
    let obj = od.find(e.index, e.sub).map_err(|err| {
        if err == OdError::INDEX {
            refuse::NO_OBJECT
        } else {
            refuse::NO_SUBINDEX
        }
    })?;
    let access = obj.access();
    let direction_ok = match dir {
        Direction::Tx => access.readable(),
        Direction::Rx => access.writable(),
    };
    if !access.mappable() || !direction_ok {
        return Err(refuse::NOT_MAPPABLE);
    }
    length_ok(obj.data_type(), e.bits, rules)?;
    Ok(e.bits)
}

/// Checks a whole mapping; returns the total length in bits.
pub fn check_mapping(
    od: &ObjectDictionary,
    dir: Direction,
    entries: &[u32],
    rules: Rules,
) -> Result<u16, OdError> {
    if entries.len() > PDO_MAX_MAPPENTRIES {
        return Err(refuse::LENGTH);
    }
    let mut total = 0u16;
    for raw in entries {
        total = total.saturating_add(u16::from(check_entry(od, dir, *raw, rules)?));
    }
    if total > MAX_BITS {
        return Err(refuse::LENGTH);
    }
    Ok(total)
}

/// The COB-ID of a PDO's communication object (bit 31 set when it cannot
/// be read: a PDO without COB-ID does not exist).
pub fn cob_id_of(od: &ObjectDictionary, commu: u16) -> u32 {
    od.read_uint(commu, 1).map_or(COB_INVALID, |v| v as u32)
}

/// Reads the mapping entries 1..=count of a mapping object into `out`;
/// `None` when one of them cannot be read.
pub fn read_entries(
    od: &ObjectDictionary,
    mapp: u16,
    count: usize,
    out: &mut [u32; PDO_MAX_MAPPENTRIES],
) -> Option<()> {
    for (i, slot) in out.iter_mut().enumerate().take(count) {
        let sub = u8::try_from(i + 1).ok()?;
        *slot = od.read_uint(mapp, sub).ok()? as u32;
    }
    Some(())
}

/// The module hook for writes to 0x1005–0x1007 and 0x1400–0x1BFF.
pub fn check_write(
    od: &ObjectDictionary,
    obj: &Object,
    value: &Staged,
    rules: Rules,
) -> Result<(), OdError> {
    let Some(v) = value.as_u64() else {
        return Ok(());
    };
    let v32 = v as u32;
    match obj.index() {
        super::SYNC_COB_ID_INDEX => check_sync_cob_id(v32),
        super::SYNC_CYCLE_INDEX | super::SYNC_WINDOW_INDEX => Ok(()),
        index => match PdoIndex::of(index) {
            Some(p) if p.role == Role::Commu => check_commu(od, p, obj.sub(), v32),
            Some(p) => check_mapp(od, p, obj.sub(), v, rules),
            None => Ok(()),
        },
    }
}

/// 0x1005 (CiA 301 §7.5.2.5): the identifier must be usable; bit 30
/// ("generate SYNC") makes this node the SYNC producer
/// ([`crate::sync`]); bit 31 is "do not care".
fn check_sync_cob_id(v: u32) -> Result<(), OdError> {
    wire::check_identifier(v & !(COB_INVALID | COB_NO_RTR), crate::config::CDRV_CAN20B)
        .map_err(|_| refuse::INVALID)
}

fn check_commu(od: &ObjectDictionary, p: PdoIndex, sub: u8, v: u32) -> Result<(), OdError> {
    let cur = cob_id_of(od, p.commu());
    let cur_valid = cur & COB_INVALID == 0;
    match sub {
        1 => {
            let new_valid = v & COB_INVALID == 0;
            // CiA 301 §7.5.2.35/37: bits 0-29 (frame format and
            // identifier) must not change while the PDO exists; switching
            // bit 31 is the way. Bit 30 (remote requests) may.
            if cur_valid && new_valid && (v ^ cur) & !COB_NO_RTR != 0 {
                return Err(refuse::INVALID);
            }
            if new_valid {
                wire::check_identifier(v, crate::config::CDRV_CAN20B)
                    .map_err(|_| refuse::INVALID)?;
                if !cur_valid {
                    check_current_mapping(od, p)?;
                }
            }
            Ok(())
        }
        2 => {
            let t = v as u8;
            let ok = match p.dir {
                Direction::Tx => tx_type::valid_for_tpdo(t),
                Direction::Rx => tx_type::valid_for_rpdo(t),
            };
            if ok { Ok(()) } else { Err(refuse::INVALID) }
        }
        // CiA 301 §7.5.2.37: the inhibit time of a TPDO shall not change
        // while the PDO exists.
        3 if p.dir == Direction::Tx && cur_valid => Err(refuse::INVALID),
        _ => Ok(()),
    }
}

/// Before a PDO becomes valid its mapping must hold (a default mapping in
/// objdict.h may name an object that does not exist).
fn check_current_mapping(od: &ObjectDictionary, p: PdoIndex) -> Result<(), OdError> {
    if od.find_entry(p.mapp()).is_none() {
        // A PDO without mapping object carries static data (or nothing).
        return Ok(());
    }
    let count = od.read_uint(p.mapp(), 0).unwrap_or(0) as usize;
    let mut entries = [0u32; PDO_MAX_MAPPENTRIES];
    if count > PDO_MAX_MAPPENTRIES {
        return Err(refuse::LENGTH);
    }
    read_entries(od, p.mapp(), count, &mut entries).ok_or(refuse::LENGTH)?;
    check_mapping(od, p.dir, entries.get(..count).unwrap_or(&[]), RULES).map(|_| ())
}

fn check_mapp(
    od: &ObjectDictionary,
    p: PdoIndex,
    sub: u8,
    v: u64,
    rules: Rules,
) -> Result<(), OdError> {
    // Step 1 of the CiA 301 mapping procedure: the PDO must not exist.
    if cob_id_of(od, p.commu()) & COB_INVALID == 0 {
        return Err(refuse::STATE);
    }
    let count = od.read_uint(p.mapp(), 0).unwrap_or(0);
    if sub == 0 {
        // Step 4: enabling the mapping checks every entry it covers.
        let n = usize::try_from(v).unwrap_or(usize::MAX);
        let capacity = od
            .find_entry(p.mapp())
            .map_or(0, |e| od.sub_count(e).saturating_sub(1));
        if n > PDO_MAX_MAPPENTRIES || n > capacity {
            return Err(refuse::LENGTH);
        }
        let mut entries = [0u32; PDO_MAX_MAPPENTRIES];
        read_entries(od, p.mapp(), n, &mut entries).ok_or(refuse::LENGTH)?;
        return check_mapping(od, p.dir, entries.get(..n).unwrap_or(&[]), rules).map(|_| ());
    }
    // Step 3: entries change only while subindex 0 is 0.
    if count != 0 {
        return Err(refuse::STATE);
    }
    if v == 0 {
        return Ok(());
    }
    check_entry(od, p.dir, v as u32, rules).map(|_| ())
}
