//! Store and restore parameters (CiA 301 7.5.2.13 and 7.5.2.14; objects
//! 0x1010 and 0x1011): the SYS TEC module STORE (`CcmInitStore`,
//! `CcmStoreCheckArchivState`, `CcmStoreRestoreDefault`, the OBD callbacks
//! `CcmCbStore` / `CcmCbRestore`).
//!
//! This library has no non-volatile storage driver. It says so instead of
//! pretending:
//! * "save" (0x65766173) written to 0x1010 sub 1.. is refused with SDO
//!   abort 0x08000020 (data cannot be stored; `kCopCcmStoreHwError` for
//!   `CcmWriteObject`); so is any other value (wrong signature, CiA 301).
//!   After each reset communication the subindices 1.. of 0x1010 are set to
//!   0 where the dictionary lets them be written: "the device does not save
//!   parameters" (CiA 301 7.5.2.13, bits 0 and 1).
//! * "load" (0x64616F6C) written to 0x1011 sub 1.. is accepted: the
//!   defaults of the selected parameters are restored at the next reset
//!   (reset node for every selection, reset communication for the
//!   communication parameters). Because nothing is ever stored, every reset
//!   of this library starts from the defaults anyway; the request is kept
//!   only so that it can be inspected ([`StoreRestore::restore_requested`]).
//!   Other values are refused with 0x08000020. The subindex keeps reading 1
//!   ("the device restores parameters").
//! * Writing back the value a subindex of 0x1010 / 0x1011 reads (0 or 1,
//!   as configuration tools and DCF containers do when they download every
//!   writable object) is accepted and changes nothing; any other value that
//!   is not the signature is refused as above, also in a `DynBuildOd`
//!   container.
//! * Selections of 0x1011 (and of `tObdPart`): sub 1 all parameters, sub 2
//!   the communication parameters (0x1000–0x1FFF, `kObdPartGen`), sub 3 and
//!   the manufacturer-specific subs 4.. the application parameters
//!   (0x2000–0x9FFF and a dynamic user part, `kObdPartApp2`).

pub mod image;

use crate::error::{CopKernel, CopResult, OdError, SdoAbort};
use crate::od::{Object, ObjectDictionary, Staged};

/// Store parameters.
pub const SAVE_INDEX: u16 = 0x1010;
/// Restore default parameters.
pub const LOAD_INDEX: u16 = 0x1011;
/// The signature "save" as an UNSIGNED32 (ISO 8859 characters, LSB first).
pub const SAVE_SIGNATURE: u32 = 0x6576_6173;
/// The signature "load".
pub const LOAD_SIGNATURE: u32 = 0x6461_6F6C;

/// `tObdPart` bits (`kObdPart*`).
pub mod part {
    /// kObdPartGen: 0x1000–0x1FFF.
    pub const GEN: u8 = 0x01;
    /// kObdPartMan: 0x2000–0x5FFF.
    pub const MAN: u8 = 0x02;
    /// kObdPartDev: 0x6000–0x9FFF.
    pub const DEV: u8 = 0x04;
    /// kObdPartUsr: the dynamic / user part.
    pub const USR: u8 = 0x08;
    /// kObdPartApp2: the application parameters.
    pub const APP: u8 = MAN | DEV | USR;
    /// kObdPartAll.
    pub const ALL_PARTS: u8 = GEN | APP;
}

/// A write to 0x1010 sub 1..: never stored (no storage).
pub const REFUSE_SAVE: OdError = OdError::new(CopKernel::CcmStoreHwError, SdoAbort::CannotStore);
/// A value other than the signature (CiA 301: abort 0x08000020).
pub const REFUSE_SIGNATURE: OdError = OdError::new(CopKernel::InvalidParam, SdoAbort::CannotStore);

/// `CcmStoreCheckArchivState` / part arguments: a non-empty combination of
/// the `kObdPart*` bits. kCopObdIllegalPart otherwise.
pub fn check_part(p: u32) -> CopResult {
    if p == 0 || p & !u32::from(part::ALL_PARTS) != 0 {
        Err(CopKernel::ObdIllegalPart)
    } else {
        Ok(())
    }
}

/// The parts a subindex of 0x1011 selects.
pub const fn selection(sub: u8) -> u8 {
    match sub {
        0 => 0,
        1 => part::ALL_PARTS,
        2 => part::GEN,
        _ => part::APP,
    }
}

/// The store / restore bookkeeping.
#[derive(Clone, Copy, Debug, Default)]
pub struct StoreRestore {
    restore_requested: u8,
}

impl StoreRestore {
    /// Nothing requested.
    pub const fn new() -> Self {
        StoreRestore {
            restore_requested: 0,
        }
    }

    /// The `kObdPart*` bits whose defaults a "load" (or
    /// `CcmStoreRestoreDefault`) asked for and no reset has restored yet.
    pub fn restore_requested(&self) -> u8 {
        self.restore_requested
    }

    /// Asks for the defaults of `parts` at the next reset.
    pub fn request_restore(&mut self, parts: u8) {
        self.restore_requested |= parts & part::ALL_PARTS;
    }

    /// A reset restored the defaults of `parts`.
    pub fn restored(&mut self, parts: u8) {
        self.restore_requested &= !parts;
    }

    /// Module hook: judges writes to 0x1010 / 0x1011 sub 1.. (sub 0 follows
    /// the dictionary's access rights alone).
    pub fn check_write(od: &ObjectDictionary, obj: &Object, value: &Staged) -> Result<(), OdError> {
        let index = obj.index();
        if obj.sub() == 0 || !matches!(index, SAVE_INDEX | LOAD_INDEX) {
            return Ok(());
        }
        let v = value.as_u64();
        if index == SAVE_INDEX && v == Some(u64::from(SAVE_SIGNATURE)) {
            return Err(REFUSE_SAVE);
        }
        if index == LOAD_INDEX && v == Some(u64::from(LOAD_SIGNATURE)) {
            return Ok(());
        }
        if v.is_some() && v == od.read_uint(index, obj.sub()).ok() {
            // The value the subindex reads: a write-back, no command.
            return Ok(());
        }
        Err(REFUSE_SIGNATURE)
    }

    /// Module hook after an accepted write: a "load" is recorded and the
    /// subindex reads 1 again.
    pub fn after_store(&mut self, od: &ObjectDictionary, obj: &Object) {
        if obj.index() == LOAD_INDEX
            && obj.sub() != 0
            && od.read_uint(LOAD_INDEX, obj.sub()) == Ok(u64::from(LOAD_SIGNATURE))
        {
            self.request_restore(selection(obj.sub()));
            let _ = od.poke_uint(LOAD_INDEX, obj.sub(), 1);
        }
    }

    /// After reset communication: 0x1010 sub 1.. read 0 ("does not save"),
    /// where the dictionary keeps them in RAM.
    pub fn reconfigure(&self, od: &ObjectDictionary) {
        let Some(entry) = od.find_entry(SAVE_INDEX) else {
            return;
        };
        for sub in 1..od.sub_count(entry) {
            if let Ok(sub) = u8::try_from(sub) {
                let _ = od.poke_uint(SAVE_INDEX, sub, 0);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signatures_are_the_ascii_words() {
        assert_eq!(SAVE_SIGNATURE.to_le_bytes(), *b"save");
        assert_eq!(LOAD_SIGNATURE.to_le_bytes(), *b"load");
    }

    #[test]
    fn parts_and_selections() {
        assert_eq!(check_part(0), Err(CopKernel::ObdIllegalPart));
        assert_eq!(check_part(0x10), Err(CopKernel::ObdIllegalPart));
        assert!(check_part(u32::from(part::GEN)).is_ok());
        assert!(check_part(u32::from(part::ALL_PARTS)).is_ok());
        assert_eq!(selection(1), part::ALL_PARTS);
        assert_eq!(selection(2), part::GEN);
        assert_eq!(selection(3), part::APP);
        assert_eq!(selection(9), part::APP);
        let mut s = StoreRestore::new();
        s.request_restore(part::ALL_PARTS);
        s.restored(part::GEN);
        assert_eq!(s.restore_requested(), part::APP);
        s.restored(part::APP);
        assert_eq!(s.restore_requested(), 0);
    }
}
