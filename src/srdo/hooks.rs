//! What a write to 0x1300..0x13FF may do. The stack calls these hooks for
//! SDO downloads and `CcmWriteObject` alike (SAFETY_BEHAVIOUR.md section 2).
//!
//! | write | refused when | kernel code | SDO abort |
//! |---|---|---|---|
//! | any SRDO object | node OPERATIONAL | `kCopSrdoNmtError` | 0x08000022 |
//! | 0x1300 | value not 0 or 1 | `kCopObdValueToHigh` | 0x06090030 |
//! | 0x1301+n sub 1 | direction > 2 | `kCopObdValueToHigh` | 0x06090030 |
//! | sub 2 / sub 3 | 0 while direction ≠ 0 | `kCopSrdoCfgTimingError` | 0x06090030 |
//! | sub 4 | not 254 | `kCopSrdoInvalidCfg` | 0x06090030 |
//! | sub 5 / sub 6 | direction ≠ 0 and another value than the one in force | `kCopSrdoInvalidCfg` | 0x06090030 |
//! | sub 5 | not odd in 0x101..=0x17F (bits 31..11 zero) | `kCopSrdoCfgIdError` | 0x06090030 |
//! | sub 6 | not even in 0x102..=0x180 (bits 31..11 zero) | `kCopSrdoCfgIdError` | 0x06090030 |
//! | 0x1381+n any sub | direction ≠ 0 and another value than the one in force | `kCopSrdoInvalidCfg` | 0x06090030 |
//! | 0x1381+n sub 0 | above `SRDO_MAX_MAPPENTRIES` or the entries present | `kCopSrdoErrorMapp` | 0x06040042 |
//! | 0x1381+n sub 0 = n | odd, or a pair of unequal length | `kCopSrdoErrorMapp` | 0x06040043 |
//! | | an entry of the n refused as below | as below | as below |
//! | | more than 8 bytes of normal data | `kCopSrdoLengthExceeded` | 0x06040042 |
//! | 0x1381+n sub 1.. (not 0) | the object does not exist | `kCopSrdoErrorMapp` | 0x06020000 / 0x06090011 |
//! | | not mappable, wrong length, no variable, access not for the declared direction, dummy not allowed | `kCopSrdoErrorMapp` | 0x06040041 |
//! | | length not a multiple of `SRDO_GRANULARITY` (sub 0: any entry) | `kCopSrdoGranularityMismatch` | 0x06040043 |
//! | 0x13FE = 0xA5 | the configuration check fails | the check's code | 0x08000020 |
//!
//! A refused write changes nothing, 0x13FE included. An accepted write to a
//! safety parameter (0x1301..0x1340, 0x1381..0x13C0, 0x13FF) sets 0x13FE to
//! 0 just before the value is stored. Whether COB-ID 1 and 2 form a pair
//! is left to the configuration check, because a configuration tool writes
//! one value at a time; the mapping is checked at each change (manual 2.5,
//! `check::mapping_write`): an entry on its own, the count with the
//! entries it enables. The direction the objects' access must fit is the
//! one the dictionary declares for the SRDO (the direction is 0 while the
//! mapping changes); the check at 0xA5 judges the direction in force.

use super::{
    COMMU_FIRST, COMMU_LAST, CONFIG_VALID, CONFIG_VALID_INDEX, CRC_INDEX, Direction,
    GFC_PARAM_INDEX, MAPP_FIRST, MAPP_LAST, MAPP_OFFSET, Srdo, TRANSMISSION_TYPE, read_u8,
};
use crate::config::SRDO_GRANULARITY;
use crate::error::{CopKernel, OdError, SdoAbort};
use crate::event::NmtState;
use crate::od::{Object, ObjectDictionary, Staged};
use crate::wire::srdo::{COB_ID_MAX, COB_ID_MIN, COB_ID_RESERVED_MASK};

/// Which SRDO object a write addresses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Target {
    Gfc,
    Commu(u16),
    Mapp(u16),
    ConfigValid,
    Crc,
}

fn range(kernel: CopKernel) -> OdError {
    OdError::new(kernel, SdoAbort::ValueRange)
}

impl Srdo {
    fn target(&self, index: u16) -> Option<Target> {
        match index {
            GFC_PARAM_INDEX => Some(Target::Gfc),
            CONFIG_VALID_INDEX => Some(Target::ConfigValid),
            CRC_INDEX => Some(Target::Crc),
            COMMU_FIRST..=COMMU_LAST => self.slot_for(index).ok().map(|_| Target::Commu(index)),
            MAPP_FIRST..=MAPP_LAST => self
                .slot_for(index - MAPP_OFFSET)
                .ok()
                .map(|_| Target::Mapp(index - MAPP_OFFSET)),
            _ => None,
        }
    }

    /// Module hook: may refuse a write to 0x1300..0x13FF (table in the
    /// module docs). Reads the dictionary only.
    pub fn check_write(
        &self,
        od: &ObjectDictionary,
        obj: &Object,
        value: &Staged,
        state: NmtState,
    ) -> Result<(), OdError> {
        let Some(target) = self.target(obj.index()) else {
            return Ok(());
        };
        if state == NmtState::Operational {
            return Err(OdError::new(CopKernel::SrdoNmtError, SdoAbort::DeviceState));
        }
        let v = value.as_u64().unwrap_or(0);
        // Manual 1.1.1 restricts changes: the value in force written again
        // changes nothing and passes the direction rules.
        let same = od.read_uint(obj.index(), obj.sub()) == Ok(v);
        match target {
            Target::Gfc => {
                if v > 1 {
                    return Err(range(CopKernel::ObdValueToHigh));
                }
            }
            Target::ConfigValid => {
                if v == u64::from(CONFIG_VALID) {
                    self.check_config(od)
                        .map_err(|(code, _)| OdError::new(code, SdoAbort::CannotStore))?;
                }
            }
            Target::Crc => {}
            Target::Commu(commu_index) => check_commu(od, commu_index, obj.sub(), v, same)?,
            Target::Mapp(commu_index) => {
                if direction(od, commu_index) != Some(Direction::Off as u8) {
                    return if same {
                        Ok(())
                    } else {
                        Err(range(CopKernel::SrdoInvalidCfg))
                    };
                }
                super::check::mapping_write(od, commu_index, obj.sub(), v, SRDO_GRANULARITY)?;
            }
        }
        Ok(())
    }

    /// Module hook: the write will happen now. A safety parameter makes the
    /// configuration invalid (0x13FE := 0) before its value changes.
    pub fn before_store(&mut self, od: &ObjectDictionary, obj: &Object, value: &Staged) {
        let _ = value;
        if matches!(
            self.target(obj.index()),
            Some(Target::Commu(_) | Target::Mapp(_) | Target::Crc)
        ) {
            // 0x13FE exists whenever an SRDO does (checked at init).
            let _ = od.poke_uint(CONFIG_VALID_INDEX, 0, 0);
            self.config_valid = false;
        }
    }

    /// Module hook: the write happened; the cached 0x1300 and 0x13FE follow.
    pub fn after_store(&mut self, od: &ObjectDictionary, obj: &Object) {
        if let Some(Target::Gfc | Target::ConfigValid) = self.target(obj.index()) {
            self.load_cached(od);
        }
    }
}

fn direction(od: &ObjectDictionary, commu_index: u16) -> Option<u8> {
    read_u8(od, commu_index, 1)
}

fn check_commu(
    od: &ObjectDictionary,
    commu_index: u16,
    sub: u8,
    v: u64,
    same: bool,
) -> Result<(), OdError> {
    let off = direction(od, commu_index) == Some(Direction::Off as u8);
    match sub {
        1 if v > 2 => Err(range(CopKernel::ObdValueToHigh)),
        2 | 3 if v == 0 && !off => Err(range(CopKernel::SrdoCfgTimingError)),
        4 if v != u64::from(TRANSMISSION_TYPE) => Err(range(CopKernel::SrdoInvalidCfg)),
        5 | 6 if !off && same => Ok(()),
        5 | 6 if !off => Err(range(CopKernel::SrdoInvalidCfg)),
        5 | 6 => {
            let id = v as u32;
            let (low, high, odd) = if sub == 5 {
                (COB_ID_MIN, COB_ID_MAX - 1, true)
            } else {
                (COB_ID_MIN + 1, COB_ID_MAX, false)
            };
            let ok = id & COB_ID_RESERVED_MASK == 0
                && (u32::from(low)..=u32::from(high)).contains(&id)
                && (id & 1 == 1) == odd;
            if ok {
                Ok(())
            } else {
                Err(range(CopKernel::SrdoCfgIdError))
            }
        }
        _ => Ok(()),
    }
}
