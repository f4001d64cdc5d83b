//! Store and restore parameters (CiA 301 7.5.2.13 and 7.5.2.14; objects
//! 0x1010 and 0x1011): the SYS TEC module STORE (`CcmInitStore`,
//! `CcmStoreCheckArchivState`, `CcmStoreRestoreDefault`, the OBD callbacks
//! `CcmCbStore` / `CcmCbRestore`).
//!
//! Without a storage driver (the default) nothing is stored:
//! `CcmInitStore` returns kCopCcmStoreHwError and start-up goes on with the
//! dictionary's defaults; "save" on 0x1010 is refused with SDO abort
//! 0x08000020; 0x1010 sub 1.. read 0 ("does not save"). "load" on 0x1011
//! sub 1.. is accepted either way: the defaults of the selected parameters
//! are restored at the next reset (reset node for every selection, reset
//! communication for the communication parameters).
//!
//! With a driver ([`StorageDriver`], from C `tCopStoreDriver`) and after
//! `CcmInitStore`:
//! * "save" (0x65766173) on 0x1010 sub n writes a new image ([`image`]) of
//!   the selected parts, keeping the others as stored; only after the
//!   image is complete does the SDO download succeed. Refusals: SDO abort
//!   0x08000022 / kCopCcmStoreUnvalidState while OPERATIONAL (the stored
//!   SRDO configuration would not be the one the node checked when it
//!   became OPERATIONAL: CiA 304 changes the safety configuration only in
//!   PRE-OPERATIONAL, and so does this library's store); 0x08000020 /
//!   kCopCcmStoreHwError for a driver error or a full memory (the previous
//!   image stays in force).
//! * "load" (0x64616F6C) on 0x1011 sub n removes the selected parts from
//!   the image (a new image without them) and restores their defaults at
//!   the next reset.
//! * Every reset node loads the stored application parts after restoring
//!   the defaults, every reset communication the stored communication
//!   part; `CcmInitStore` loads everything at once. A restored 0x13FE is
//!   taken as stored; the SRDOs run only if the configuration check (with
//!   the 0x13FF CRCs) passes when the node enters OPERATIONAL.
//! * Subindices: sub 1 all parameters, sub 2 communication (0x1000–0x1FFF,
//!   `kObdPartGen`), sub 3 application (0x6000–0x9FFF, `kObdPartDev`),
//!   sub 4..0x7F manufacturer specific (0x2000–0x5FFF, `kObdPartMan`)
//!   (CiA 301 7.5.2.13). They read 1 ("saves on command") once a driver is
//!   in use, else 0.
//! * Stored objects: every writable RAM subindex of the three parts up to
//!   [`image::OBJECT_MAX`] bytes, except 0x1003, 0x1010 and 0x1011.
//! * Writing back the value a subindex reads (as configuration tools do)
//!   is accepted and changes nothing; any other value that is not the
//!   signature is refused with 0x08000020 (CiA 301).

pub mod image;

use crate::error::{CopKernel, CopResult, OdError, SdoAbort};
use crate::event::NmtState;
use crate::od::{ByteOrder, Object, ObjectDictionary, Part, Staged, Storage};
use image::{ImageError, NvFault, NvMemory, Records, Visit};

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

/// A write to 0x1010 sub 1.. without a driver, or the driver failed.
pub const REFUSE_SAVE: OdError = OdError::new(CopKernel::CcmStoreHwError, SdoAbort::CannotStore);
/// "save" while OPERATIONAL.
pub const REFUSE_STATE: OdError =
    OdError::new(CopKernel::CcmStoreUnvalidState, SdoAbort::DeviceState);

/// The application's non-volatile memory as the stack uses it: the same
/// operations as [`NvMemory`] on a shared reference (the C driver is a
/// table of functions; see `tCopStoreDriver` in `include/target.h`).
pub trait StorageDriver {
    /// Usable bytes.
    fn size(&self) -> u32;
    /// Write granularity (power of two, at most [`image::CHUNK`]).
    fn align(&self) -> u32;
    /// Reads `out.len()` bytes at `offset`.
    fn read(&self, offset: u32, out: &mut [u8]) -> Result<(), NvFault>;
    /// Writes `data` at `offset`.
    fn write(&self, offset: u32, data: &[u8]) -> Result<(), NvFault>;
    /// Erases `len` bytes at `offset`.
    fn erase(&self, offset: u32, len: u32) -> Result<(), NvFault>;
    /// Makes the writes durable.
    fn commit(&self) -> Result<(), NvFault>;
}

/// A [`StorageDriver`] as an [`NvMemory`].
///
/// The driver is the module's only call through a pointer (the image code
/// is generic over [`NvMemory`] and [`Records`], its visitors are
/// closures called directly). The methods stay out of line, so that every
/// call of a driver function goes through one of them: the worst-case stack
/// analysis (scripts/tms570/stack.py, docs/tms570.md) resolves exactly these
/// calls to the [`StorageDriver`] implementations.
struct Nv<'a>(&'a dyn StorageDriver);

impl NvMemory for Nv<'_> {
    #[inline(never)]
    fn size(&self) -> u32 {
        self.0.size()
    }
    #[inline(never)]
    fn align(&self) -> u32 {
        self.0.align()
    }
    #[inline(never)]
    fn read(&mut self, offset: u32, out: &mut [u8]) -> Result<(), NvFault> {
        self.0.read(offset, out)
    }
    #[inline(never)]
    fn write(&mut self, offset: u32, data: &[u8]) -> Result<(), NvFault> {
        self.0.write(offset, data)
    }
    #[inline(never)]
    fn erase(&mut self, offset: u32, len: u32) -> Result<(), NvFault> {
        self.0.erase(offset, len)
    }
    #[inline(never)]
    fn commit(&mut self) -> Result<(), NvFault> {
        self.0.commit()
    }
}

/// The registered driver.
#[derive(Clone, Copy)]
pub struct Driver(pub &'static dyn StorageDriver);

impl core::fmt::Debug for Driver {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Driver")
    }
}

/// The image's part bits of a `kObdPart*` combination.
const fn image_parts(p: u8) -> u8 {
    p & (part::GEN | part::MAN | part::DEV)
}

/// Objects that are never stored: the error history and the commands.
const fn excluded(index: u16) -> bool {
    matches!(index, 0x1003 | SAVE_INDEX | LOAD_INDEX)
}

/// The dictionary as image records.
pub struct OdRecords<'a>(pub &'a ObjectDictionary);

impl OdRecords<'_> {
    /// Calls `f` for every stored object of the image part `p`.
    fn objects<F: FnMut(&Object) -> Result<(), ImageError>>(
        &self,
        p: u8,
        f: &mut F,
    ) -> Result<(), ImageError> {
        let od = self.0;
        for entry in od.entries() {
            let index = entry.index();
            let in_part = match Part::of(index) {
                Part::Generic => part::GEN,
                Part::Manufacturer => part::MAN,
                Part::Device => part::DEV,
                Part::User => 0,
            };
            if in_part & p == 0 || excluded(index) {
                continue;
            }
            for sub in 0..od.sub_count(entry) {
                let Ok(sub) = u8::try_from(sub) else { break };
                let Ok(obj) = od.find(index, sub) else {
                    continue;
                };
                if stored(&obj) {
                    f(&obj)?;
                }
            }
        }
        Ok(())
    }
}

/// Whether an object is part of the image.
fn stored(obj: &Object) -> bool {
    obj.access().writable()
        && matches!(
            obj.storage(),
            Ok(Storage::Ram(_) | Storage::RamString(_) | Storage::Var(_))
        )
        && obj.native_size().is_ok_and(|n| n <= image::OBJECT_MAX)
}

impl Records for OdRecords<'_> {
    fn signature(&self) -> u32 {
        let mut d = image::SignatureDigest::new();
        let _ = self.objects(part::GEN | part::MAN | part::DEV, &mut |o| {
            d.object(
                o.index(),
                o.sub(),
                o.native_size().unwrap_or(0),
                o.data_type().code(),
            );
            Ok(())
        });
        d.finish()
    }

    fn each<F: Visit + ?Sized>(&self, p: u8, f: &mut F) -> Result<(), ImageError> {
        let od = self.0;
        self.objects(p, &mut |o| {
            let mut buf = [0u8; image::OBJECT_MAX];
            let n = od
                .peek(o, ByteOrder::Wire, &mut buf)
                .map_err(|_| ImageError::Rejected)?;
            f(o.index(), o.sub(), buf.get(..n).unwrap_or(&[]))
        })
    }

    fn check(&self, index: u16, sub: u8, value: &[u8]) -> bool {
        let od = self.0;
        od.find(index, sub).is_ok_and(|o| {
            stored(&o) && !excluded(index) && od.stage(&o, ByteOrder::Wire, value).is_ok()
        })
    }

    fn apply(&mut self, index: u16, sub: u8, value: &[u8]) -> Result<(), ImageError> {
        let od = self.0;
        let o = od.find(index, sub).map_err(|_| ImageError::Rejected)?;
        let staged = od
            .stage(&o, ByteOrder::Wire, value)
            .map_err(|_| ImageError::Rejected)?;
        od.store(&o, &staged, value)
            .map_err(|_| ImageError::Rejected)
    }
}

/// The `tCopKernel` of an image failure.
pub const fn kernel_of(e: ImageError) -> CopKernel {
    match e {
        ImageError::Driver | ImageError::Geometry | ImageError::Full => CopKernel::CcmStoreHwError,
        ImageError::NoImage | ImageError::Foreign | ImageError::Rejected => {
            CopKernel::CcmStoreUnvalidState
        }
    }
}
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
        3 => part::DEV,
        _ => part::MAN,
    }
}

/// The store / restore bookkeeping.
#[derive(Clone, Copy, Debug, Default)]
pub struct StoreRestore {
    restore_requested: u8,
    driver: Option<Driver>,
    key: u32,
    /// `CcmInitStore` found the driver usable.
    ready: bool,
    /// The last image failure seen (`None` after a success).
    last: Option<ImageError>,
}

impl StoreRestore {
    /// Nothing requested, no driver.
    pub const fn new() -> Self {
        StoreRestore {
            restore_requested: 0,
            driver: None,
            key: 0,
            ready: false,
            last: None,
        }
    }

    /// Registers the application's storage (`None`: no storage) and the
    /// configuration key written into and required of every image
    /// (`OD_BUILDER_KEY`). Takes effect with the next [`Self::init`].
    pub fn set_driver(&mut self, driver: Option<Driver>, key: u32) {
        self.driver = driver;
        self.key = key;
        self.ready = false;
    }

    /// Whether "save" is served (a driver and a successful `CcmInitStore`).
    pub fn ready(&self) -> bool {
        self.ready
    }

    /// Why the last load or store failed; `None` after a success.
    pub fn last_error(&self) -> Option<ImageError> {
        self.last
    }

    fn note<T>(&mut self, r: Result<T, ImageError>) -> Result<T, ImageError> {
        self.last = r.as_ref().err().copied();
        r
    }

    /// `CcmInitStore`: checks the memory and loads every stored part.
    /// kCopCcmStoreHwError without a driver (start-up goes on with the
    /// defaults) or for a driver that fails; kCopCcmStoreUnvalidState for
    /// an image of another dictionary (ignored; the next "save" replaces
    /// it); kCopSuccessful with or without a stored image.
    pub fn init(&mut self, od: &ObjectDictionary) -> CopResult {
        let Some(Driver(d)) = self.driver else {
            self.ready = false;
            return Err(CopKernel::CcmStoreHwError);
        };
        let mut recs = OdRecords(od);
        let r = image::load(
            &mut Nv(d),
            &mut recs,
            self.key,
            part::GEN | part::MAN | part::DEV,
        );
        let r = self.note(r);
        match r {
            Ok(_) | Err(ImageError::NoImage) => {
                self.ready = true;
                self.last = None;
                Ok(())
            }
            Err(e @ (ImageError::Foreign | ImageError::Rejected)) => {
                self.ready = true;
                Err(kernel_of(e))
            }
            Err(e) => {
                self.ready = false;
                Err(kernel_of(e))
            }
        }
    }

    /// Loads the stored `parts` after a reset restored their defaults
    /// (nothing without a driver or image).
    pub fn load_parts(&mut self, od: &ObjectDictionary, parts: u8) {
        if let (true, Some(Driver(d))) = (self.ready, self.driver) {
            let mut recs = OdRecords(od);
            let r = image::load(&mut Nv(d), &mut recs, self.key, image_parts(parts));
            let _ = self.note(r);
        }
    }

    /// `CcmStoreCheckArchivState`: kCopSuccessful when a valid image holds
    /// every part of `parts`, kCopCcmStoreUnvalidState otherwise,
    /// kCopCcmStoreHwError without a driver.
    pub fn check_archive(&self, od: &ObjectDictionary, parts: u8) -> CopResult {
        let (true, Some(Driver(d))) = (self.ready, self.driver) else {
            return Err(CopKernel::CcmStoreHwError);
        };
        let want = image_parts(parts);
        if want == 0 {
            return Err(CopKernel::CcmStoreUnvalidState);
        }
        image::holds(&mut Nv(d), &OdRecords(od), self.key, want).map_err(kernel_of)
    }

    /// `CcmStoreRestoreDefault`: erases the image (when there is a
    /// driver) and restores every default at the next reset.
    pub fn restore_default(&mut self) -> CopResult {
        self.request_restore(part::ALL_PARTS);
        if let (true, Some(Driver(d))) = (self.ready, self.driver) {
            let r = image::erase_all(&mut Nv(d));
            self.note(r).map_err(kernel_of)?;
        }
        Ok(())
    }

    /// "save" of `parts` (`kObdPart*` bits) without the object 0x1010:
    /// the same rules and refusals as the write of the signature.
    pub fn save(
        &mut self,
        od: &ObjectDictionary,
        parts: u8,
        state: NmtState,
    ) -> Result<(), OdError> {
        if !self.ready {
            return Err(REFUSE_SAVE);
        }
        if state == NmtState::Operational {
            return Err(REFUSE_STATE);
        }
        self.write_image(od, parts, 0)
    }

    /// Writes a new image: `fresh` from the dictionary, `drop` left out,
    /// the rest kept.
    fn write_image(&mut self, od: &ObjectDictionary, fresh: u8, drop: u8) -> Result<(), OdError> {
        let (true, Some(Driver(d))) = (self.ready, self.driver) else {
            return Err(REFUSE_SAVE);
        };
        let r = image::store(
            &mut Nv(d),
            &OdRecords(od),
            self.key,
            image_parts(fresh),
            image_parts(drop),
        );
        self.note(r).map(|_| ()).map_err(|_| REFUSE_SAVE)
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
    /// the dictionary's access rights alone) and carries out "save" and,
    /// with a driver, the removal of the parts a "load" selects.
    pub fn check_write(
        &mut self,
        od: &ObjectDictionary,
        obj: &Object,
        value: &Staged,
        state: NmtState,
    ) -> Result<(), OdError> {
        let index = obj.index();
        if obj.sub() == 0 || !matches!(index, SAVE_INDEX | LOAD_INDEX) {
            return Ok(());
        }
        let v = value.as_u64();
        let parts = selection(obj.sub());
        if index == SAVE_INDEX && v == Some(u64::from(SAVE_SIGNATURE)) {
            return self.save(od, parts, state);
        }
        if index == LOAD_INDEX && v == Some(u64::from(LOAD_SIGNATURE)) {
            if self.ready {
                self.write_image(od, 0, parts)?;
            }
            return Ok(());
        }
        if v.is_some() && v == od.read_uint(index, obj.sub()).ok() {
            // The value the subindex reads: a write-back, no command.
            return Ok(());
        }
        Err(REFUSE_SIGNATURE)
    }

    /// Module hook after an accepted write: a "load" is recorded, and the
    /// subindex reads what it read before (the command is not a value).
    pub fn after_store(&mut self, od: &ObjectDictionary, obj: &Object) {
        if obj.sub() == 0 {
            return;
        }
        let v = od.read_uint(obj.index(), obj.sub());
        if obj.index() == LOAD_INDEX && v == Ok(u64::from(LOAD_SIGNATURE)) {
            self.request_restore(selection(obj.sub()));
            let _ = od.poke_uint(LOAD_INDEX, obj.sub(), 1);
        }
        if obj.index() == SAVE_INDEX && v == Ok(u64::from(SAVE_SIGNATURE)) {
            let _ = od.poke_uint(SAVE_INDEX, obj.sub(), u64::from(self.ready));
        }
    }

    /// After reset communication: 0x1010 sub 1.. read 1 ("saves on
    /// command") with a driver in use, else 0 ("does not save"), where the
    /// dictionary keeps them in RAM.
    pub fn reconfigure(&self, od: &ObjectDictionary) {
        let Some(entry) = od.find_entry(SAVE_INDEX) else {
            return;
        };
        for sub in 1..od.sub_count(entry) {
            if let Ok(sub) = u8::try_from(sub) {
                let _ = od.poke_uint(SAVE_INDEX, sub, u64::from(self.ready));
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
        assert_eq!(selection(3), part::DEV);
        assert_eq!(selection(4), part::MAN);
        assert_eq!(selection(0x7F), part::MAN);
        let mut s = StoreRestore::new();
        s.request_restore(part::ALL_PARTS);
        s.restored(part::GEN);
        assert_eq!(s.restore_requested(), part::APP);
        s.restored(part::APP);
        assert_eq!(s.restore_requested(), 0);
    }
}
