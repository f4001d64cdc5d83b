//! The object dictionary table format shared by C and Rust.
//!
//! `include/objdef.h` turns the application's unchanged `objdict.h` into
//! arrays of these structures; Rust code builds the same arrays with the
//! `const fn` constructors below; the dynamic OD builds them in its pool.
//! The layout follows the SYS TEC `tObdEntry`/`tObdSubEntry` (same field
//! order) with two additions: the storage kind and the variable size, so the
//! core never has to guess how wide a C variable is.
//!
//! This is the one module of the core that is allowed `unsafe` (every
//! block with its `SAFETY` comment): the tables are the C application's
//! own data, so their pointers are the dictionary's storage. Every
//! accessor the core uses is safe: the invariant "each pointer in a table
//! is valid for the program's lifetime with the stated size" is established
//! by the constructors (Rust) or by objdef.h (C, checked for plausibility
//! when the dictionary is created). The C edge (`crate::ffi`) builds
//! nothing of its own here: it hands the application's tables over as they
//! are.

// The field names are those of the C structures (objdict.h, cop.h).
#![allow(non_snake_case)]

use core::ffi::c_void;
use core::sync::atomic::{AtomicPtr, AtomicU8, Ordering};

use crate::config::ObdSizeRepr;
use crate::od::{Access, DataType};

/// `tObdSize`: BYTE, WORD or DWORD according to `OBD_SUPPORTED_OBJ_SIZE`.
pub type ObdSize = ObdSizeRepr;

/// A `tObdSize` as a byte count. `tObdSize` is a BYTE, WORD or DWORD
/// (`OBD_SUPPORTED_OBJ_SIZE`), so the conversion is lossless on every
/// target with 32-bit or wider pointers (`usize::from` has no `u32` form).
#[inline]
pub const fn obd_size_len(size: ObdSize) -> usize {
    size as usize
}

/// Storage kinds (`m_bKind`).
pub mod kind {
    /// `m_pCurrent` points to `m_dwSize` bytes of RAM (the variable).
    pub const RAM: u8 = 0;
    /// Constant: the value is at `m_pDefault` (`m_dwSize` bytes).
    pub const ROM: u8 = 1;
    /// Visible string in RAM: `m_pCurrent` points to `m_dwSize + 1` bytes,
    /// `m_pDefault` to the NUL-terminated default.
    pub const RAM_VSTRING: u8 = 2;
    /// Constant visible string: `m_pDefault` points to `m_dwSize` bytes.
    pub const ROM_VSTRING: u8 = 3;
    /// `m_pCurrent` points to a `tObdVarEntry` that the application fills
    /// (USERDEF, DOMAIN, VARARRAY elements).
    pub const VAR_ENTRY: u8 = 4;
}

/// `tObdCbParam`: what an OBD callback receives.
#[repr(C)]
#[derive(Debug)]
pub struct ObdCbParam {
    /// `tObdEvent` (kObdEv*).
    pub m_ObdEvent: u8,
    /// Index.
    pub m_wIndex: u16,
    /// Subindex.
    pub m_bSubIndex: u8,
    /// Event-dependent data (see cop.h).
    pub m_pArg: *mut c_void,
    /// SDO abort code the callback may set when it refuses.
    pub m_dwAbortCode: u32,
}

/// `tObdVStringDomain`: what kObdEvWrStringDomain hands to the callback,
/// which may change the object's size and data pointer before a string or
/// domain is written.
#[repr(C)]
#[derive(Debug)]
pub struct ObdVStringDomain {
    /// Number of bytes about to be written.
    pub m_DownloadSize: ObdSize,
    /// Current object size (capacity); the callback may change it.
    pub m_ObjSize: ObdSize,
    /// Current data pointer; the callback may change it.
    pub m_pData: *mut c_void,
}

/// What an OBD or variable callback of the application receives before its
/// own argument (`CCM_DECL_INSTANCE_HDL_`): the instance handle of the C
/// API in a multi-instance build (`COP_MAX_INSTANCES` > 1), nothing
/// otherwise. The dictionary keeps it for its callbacks
/// ([`crate::od::ObjectDictionary::set_callback_handle`]); it knows nothing
/// else of instances.
#[cfg(multi_instance)]
pub type CallbackHandle = u8;
/// What an OBD or variable callback receives before its own argument:
/// nothing in a single-instance build.
#[cfg(not(multi_instance))]
pub type CallbackHandle = NoHandle;

/// The [`CallbackHandle`] of a single-instance build: no value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoHandle;
/// The [`CallbackHandle`] of a dictionary nobody set one for (instance 0).
#[cfg(multi_instance)]
pub const FIRST_HANDLE: CallbackHandle = 0;
/// The [`CallbackHandle`] of a dictionary nobody set one for.
#[cfg(not(multi_instance))]
pub const FIRST_HANDLE: CallbackHandle = NoHandle;

/// `tObdCallback`.
#[cfg(not(multi_instance))]
pub type ObdCallback = unsafe extern "C" fn(param: *mut ObdCbParam) -> u32;
/// `tObdCallback` (multi-instance form).
#[cfg(multi_instance)]
pub type ObdCallback = unsafe extern "C" fn(handle: CallbackHandle, param: *mut ObdCbParam) -> u32;

/// `tVarCallback`.
#[cfg(not(multi_instance))]
pub type VarCallback = unsafe extern "C" fn(param: *mut c_void) -> u32;
/// `tVarCallback` (multi-instance form).
#[cfg(multi_instance)]
pub type VarCallback = unsafe extern "C" fn(handle: CallbackHandle, param: *mut c_void) -> u32;

/// Calls a callback of one of the two types above with `handle` first in a
/// multi-instance build.
#[cfg(multi_instance)]
macro_rules! call_back {
    ($cb:expr, $h:expr, $arg:expr) => {
        $cb($h, $arg)
    };
}
#[cfg(not(multi_instance))]
macro_rules! call_back {
    ($cb:expr, $h:expr, $arg:expr) => {{
        let NoHandle = $h;
        $cb($arg)
    }};
}

/// `tObdSubEntry` (with this library's `m_bKind` and `m_dwSize`).
#[repr(C)]
#[derive(Debug)]
pub struct ObdSubEntry {
    /// Subindex.
    pub m_bSubIndex: u8,
    /// `kObdTyp*`.
    pub m_bType: u8,
    /// `kObdAcc*`.
    pub m_bAccess: u8,
    /// One of [`kind`].
    pub m_bKind: u8,
    /// Size of the variable in bytes (`sizeof` of its C type); maximum
    /// length for strings.
    pub m_dwSize: u32,
    /// Default value, native byte order; `{default, low, high}` when the
    /// access has kObdAccRange; NULL for none.
    pub m_pDefault: *const c_void,
    /// Current value, see [`kind`].
    pub m_pCurrent: *mut c_void,
}

/// `tObdEntry`.
#[repr(C)]
#[derive(Debug)]
pub struct ObdEntry {
    /// Index; 0xFFFF ends a table that is given without length.
    pub m_wIndex: u16,
    /// The subindex table.
    pub m_pSubIndex: *const ObdSubEntry,
    /// Number of entries in `m_pSubIndex`.
    pub m_bCount: u8,
    /// Application or stack callback, or NULL.
    pub m_fpCallback: Option<ObdCallback>,
}

/// `tObdVarEntry`: a variable the application attaches at run time
/// (`CcmDefineVarTab`). Fields are atomics of the same layout as the C
/// pointer/size types so that the stack and the application may both write
/// them without undefined behaviour.
#[repr(C)]
#[derive(Debug)]
pub struct ObdVarEntry {
    /// `void MEM* m_pData`.
    pub m_pData: AtomicPtr<c_void>,
    /// `tObdSize m_Size`.
    pub m_Size: AtomicObdSize,
    /// `tVarCallback m_fpCallback` (exists unless PDO_USE_STATIC_MAPPING).
    pub m_fpCallback: AtomicPtr<c_void>,
    /// `void GENERIC* m_pArg`.
    pub m_pArg: AtomicPtr<c_void>,
}

/// Atomic with the layout of `tObdSize`.
pub type AtomicObdSize = <ObdSize as AtomicOf>::Atomic;

/// Maps an integer type to its atomic.
pub trait AtomicOf {
    /// The atomic with the same layout.
    type Atomic;
}
impl AtomicOf for u8 {
    type Atomic = core::sync::atomic::AtomicU8;
}
impl AtomicOf for u16 {
    type Atomic = core::sync::atomic::AtomicU16;
}
impl AtomicOf for u32 {
    type Atomic = core::sync::atomic::AtomicU32;
}

// SAFETY: the tables are immutable after construction; what they point to is
// either constant data or atomics, so sharing them between contexts is sound.
unsafe impl Sync for ObdSubEntry {}
// SAFETY: as above.
unsafe impl Sync for ObdEntry {}

static_assertions::assert_eq_size!(AtomicPtr<c_void>, *mut c_void);
static_assertions::assert_eq_align!(AtomicPtr<c_void>, *mut c_void);
static_assertions::assert_eq_size!(AtomicObdSize, ObdSize);
static_assertions::assert_eq_size!(Option<ObdCallback>, *const c_void);

/// Where the value of one subindex lives, as the core sees it.
#[derive(Clone, Copy, Debug)]
pub enum Storage {
    /// A variable in RAM (native byte order).
    Ram(&'static [AtomicU8]),
    /// A constant.
    Rom(&'static [u8]),
    /// A visible string in RAM: buffer of capacity + 1 (NUL) bytes.
    RamString(&'static [AtomicU8]),
    /// A constant visible string (without NUL).
    RomString(&'static [u8]),
    /// An application variable attached through a `tObdVarEntry`.
    Var(&'static ObdVarEntry),
}

/// Argument handed to an OBD callback through `m_pArg`.
pub enum CbArg<'a> {
    /// NULL.
    None,
    /// Data (source data for kObdEvPreWrite, destination for PostRead, ...).
    Data(&'a mut [u8]),
    /// The object size (kObdEvInitWrite).
    Size(&'a mut ObdSize),
    /// String/domain parameters (kObdEvWrStringDomain).
    StringDomain(&'a mut ObdVStringDomain),
}

/// The table's pointer to an optional default value (NULL for none).
const fn default_ptr(default: Option<&'static [u8]>) -> *const c_void {
    match default {
        Some(d) => d.as_ptr() as *const c_void,
        None => core::ptr::null(),
    }
}

impl ObdSubEntry {
    /// A RAM variable owned by Rust code.
    pub const fn ram(
        sub: u8,
        typ: DataType,
        access: Access,
        current: &'static [AtomicU8],
        default: Option<&'static [u8]>,
    ) -> ObdSubEntry {
        ObdSubEntry {
            m_bSubIndex: sub,
            m_bType: typ.code(),
            m_bAccess: access.0,
            m_bKind: kind::RAM,
            m_dwSize: current.len() as u32,
            m_pDefault: default_ptr(default),
            m_pCurrent: current.as_ptr() as *mut c_void,
        }
    }

    /// A communication parameter's variable (`SRW`, the form objdef.h's
    /// PDO and SRDO parameter macros give every variable subindex), with
    /// its default.
    pub const fn param(
        sub: u8,
        typ: DataType,
        current: &'static [AtomicU8],
        default: &'static [u8],
    ) -> ObdSubEntry {
        Self::ram(sub, typ, Access::SRW, current, Some(default))
    }

    /// A RAM variable with a value range: `limits` holds default, low and
    /// high value one after the other (each `current.len()` bytes, native).
    pub const fn ram_range(
        sub: u8,
        typ: DataType,
        access: Access,
        current: &'static [AtomicU8],
        limits: &'static [u8],
    ) -> ObdSubEntry {
        let mut e = Self::ram(
            sub,
            typ,
            Access(access.0 | Access::RANGE),
            current,
            Some(limits),
        );
        e.m_bAccess |= Access::RANGE;
        e
    }

    /// The element array of an array object (`OBD_ROM_INDEX_RAM_ARRAY`):
    /// subindex `sub` (normally 1) addresses the first of the elements,
    /// each `element_size` bytes; the object's subindex 0 must be a constant
    /// equal to `elements.len() / element_size` (the number of elements).
    /// A length that is not a multiple of `element_size` does not compile.
    pub const fn ram_array(
        sub: u8,
        typ: DataType,
        access: Access,
        elements: &'static [AtomicU8],
        element_size: usize,
        default: Option<&'static [u8]>,
    ) -> ObdSubEntry {
        // Evaluated at compile time in a static: a misuse is a build error.
        #[allow(clippy::panic)]
        if element_size == 0 || elements.len() % element_size != 0 {
            panic!("array length is not a multiple of the element size");
        }
        let mut e = Self::ram(sub, typ, access, elements, default);
        e.m_bAccess |= Access::ARRAY;
        e.m_dwSize = element_size as u32;
        e
    }

    /// A constant.
    pub const fn rom(sub: u8, typ: DataType, access: Access, value: &'static [u8]) -> ObdSubEntry {
        Self::constant(sub, typ, kind::ROM, access, value)
    }

    /// A constant of `kind` ([`kind::ROM`], [`kind::ROM_VSTRING`]): never
    /// writable, `value` is the whole object.
    const fn constant(
        sub: u8,
        typ: DataType,
        kind: u8,
        access: Access,
        value: &'static [u8],
    ) -> ObdSubEntry {
        ObdSubEntry {
            m_bSubIndex: sub,
            m_bType: typ.code(),
            m_bAccess: (access.0 & !Access::WRITE) | Access::CONST,
            m_bKind: kind,
            m_dwSize: value.len() as u32,
            m_pDefault: value.as_ptr() as *const c_void,
            m_pCurrent: core::ptr::null_mut(),
        }
    }

    /// A visible string in RAM; `buffer.len()` is the capacity plus one.
    /// The default is a C string (`c"..."`): the table format stores it
    /// NUL-terminated, as objdef.h does.
    pub const fn ram_string(
        sub: u8,
        access: Access,
        buffer: &'static [AtomicU8],
        default: &'static core::ffi::CStr,
    ) -> ObdSubEntry {
        ObdSubEntry {
            m_bSubIndex: sub,
            m_bType: DataType::VString.code(),
            m_bAccess: access.0,
            m_bKind: kind::RAM_VSTRING,
            m_dwSize: buffer.len().saturating_sub(1) as u32,
            m_pDefault: default.as_ptr() as *const c_void,
            m_pCurrent: buffer.as_ptr() as *mut c_void,
        }
    }

    /// A constant visible string.
    pub const fn rom_string(sub: u8, access: Access, value: &'static [u8]) -> ObdSubEntry {
        Self::constant(sub, DataType::VString, kind::ROM_VSTRING, access, value)
    }

    /// An application-attached variable (USERDEF / DOMAIN).
    pub const fn var(
        sub: u8,
        typ: DataType,
        access: Access,
        entry: &'static ObdVarEntry,
        size: u32,
        default: Option<&'static [u8]>,
    ) -> ObdSubEntry {
        ObdSubEntry {
            m_bSubIndex: sub,
            m_bType: typ.code(),
            m_bAccess: access.0 | Access::VAR,
            m_bKind: kind::VAR_ENTRY,
            m_dwSize: size,
            m_pDefault: default_ptr(default),
            m_pCurrent: entry as *const ObdVarEntry as *mut c_void,
        }
    }

    /// Subindex.
    #[inline]
    pub fn sub(&self) -> u8 {
        self.m_bSubIndex
    }

    /// Data type; `None` for a code this library does not know.
    #[inline]
    pub fn data_type(&self) -> Option<DataType> {
        DataType::from_code(u16::from(self.m_bType))
    }

    /// Access attributes.
    #[inline]
    pub fn access(&self) -> Access {
        Access(self.m_bAccess)
    }

    /// Variable size in bytes (capacity for strings).
    #[inline]
    pub fn size(&self) -> usize {
        self.m_dwSize as usize
    }

    /// The variable of element `element` of a RAM entry ([`kind::RAM`]),
    /// as [`ObdSubEntry::storage`] gives it; `None` for every other kind.
    #[inline(always)]
    pub fn ram_var(&self, element: usize) -> Option<&'static [AtomicU8]> {
        if self.m_bKind != kind::RAM || self.m_pCurrent.is_null() {
            return None;
        }
        let size = self.size();
        let offset = element.checked_mul(size)?;
        // SAFETY: RAM entries point to an object of at least (element + 1) *
        // m_dwSize bytes that lives for the whole program (a static in
        // objdict.c or a Rust static); AtomicU8 has the size and alignment
        // of u8.
        Some(unsafe {
            core::slice::from_raw_parts((self.m_pCurrent as *const AtomicU8).add(offset), size)
        })
    }

    /// The constant data of a ROM entry or ROM string ([`kind::ROM`],
    /// [`kind::ROM_VSTRING`]): `m_dwSize` bytes at `m_pDefault`.
    #[inline]
    fn rom_bytes(&self) -> Option<&'static [u8]> {
        if self.m_pDefault.is_null() {
            return None;
        }
        // SAFETY: constant entries and constant strings point to m_dwSize
        // bytes of static constant data.
        Some(unsafe { core::slice::from_raw_parts(self.m_pDefault as *const u8, self.size()) })
    }

    /// Storage of element `element` (0 for plain subindices; arrays use the
    /// element number 0..n-1 with elements laid out one after the other).
    pub fn storage(&self, element: usize) -> Option<Storage> {
        let size = self.size();
        // An element whose offset overflows does not exist (every kind).
        element.checked_mul(size)?;
        match self.m_bKind {
            kind::RAM => self.ram_var(element).map(Storage::Ram),
            kind::ROM => self.rom_bytes().map(Storage::Rom),
            kind::RAM_VSTRING => {
                if self.m_pCurrent.is_null() {
                    return None;
                }
                // SAFETY: string buffers are m_dwSize + 1 bytes of static RAM.
                Some(Storage::RamString(unsafe {
                    core::slice::from_raw_parts(self.m_pCurrent as *const AtomicU8, size + 1)
                }))
            }
            kind::ROM_VSTRING => self.rom_bytes().map(Storage::RomString),
            kind::VAR_ENTRY => {
                if self.m_pCurrent.is_null() {
                    return None;
                }
                // SAFETY: VAR_ENTRY entries point to an array of static
                // tObdVarEntry of at least element + 1 elements.
                Some(Storage::Var(unsafe {
                    &*(self.m_pCurrent as *const ObdVarEntry).add(element)
                }))
            }
            _ => None,
        }
    }

    /// The default value (native order), `size()` bytes; the first of the
    /// three values for range entries.
    pub fn default_value(&self) -> Option<&'static [u8]> {
        if self.m_pDefault.is_null() {
            return None;
        }
        let n = match self.m_bKind {
            kind::RAM_VSTRING => self.default_string_len(),
            _ => self.size(),
        };
        // SAFETY: defaults are static constant data of at least n bytes (a
        // NUL-terminated string for RAM strings, measured above).
        Some(unsafe { core::slice::from_raw_parts(self.m_pDefault as *const u8, n) })
    }

    fn default_string_len(&self) -> usize {
        let p = self.m_pDefault as *const u8;
        let mut n = 0usize;
        // SAFETY: the default of a RAM string is a NUL-terminated literal;
        // the scan stops at the NUL or at the capacity, whichever is first.
        while n < self.size() && unsafe { *p.add(n) } != 0 {
            n += 1;
        }
        n
    }

    /// Low and high limit (native order) for kObdAccRange entries.
    pub fn limits(&self) -> Option<(&'static [u8], &'static [u8])> {
        if !self.access().ranged() || self.m_pDefault.is_null() {
            return None;
        }
        let n = self.size();
        // SAFETY: range entries point to three consecutive values of
        // m_dwSize bytes (default, low, high).
        let all = unsafe { core::slice::from_raw_parts(self.m_pDefault as *const u8, 3 * n) };
        Some((all.get(n..2 * n)?, all.get(2 * n..3 * n)?))
    }
}

impl ObdEntry {
    /// A table entry built by Rust code.
    pub const fn new(
        index: u16,
        subs: &'static [ObdSubEntry],
        callback: Option<ObdCallback>,
    ) -> ObdEntry {
        ObdEntry {
            m_wIndex: index,
            m_pSubIndex: subs.as_ptr(),
            m_bCount: subs.len() as u8,
            m_fpCallback: callback,
        }
    }

    /// Index.
    #[inline]
    pub fn index(&self) -> u16 {
        self.m_wIndex
    }

    /// The subindex table.
    #[inline]
    pub fn subs(&self) -> &'static [ObdSubEntry] {
        if self.m_pSubIndex.is_null() {
            return &[];
        }
        // SAFETY: m_pSubIndex points to m_bCount static entries.
        unsafe { core::slice::from_raw_parts(self.m_pSubIndex, usize::from(self.m_bCount)) }
    }

    /// True when the entry has a callback.
    pub fn has_callback(&self) -> bool {
        self.m_fpCallback.is_some()
    }

    /// kObdEvWrStringDomain before a string or domain of `download` bytes
    /// is written to `storage`: the callback sees the download size, the
    /// object size and the data pointer, and may change the latter two. For
    /// an application variable (`tObdVarEntry`) the changes are taken over;
    /// buffers owned by the dictionary (RAM strings) cannot move, so a
    /// change there is ignored. `Err` as in [`ObdEntry::notify`].
    pub fn string_domain_event(
        &self,
        handle: CallbackHandle,
        sub: u8,
        storage: Storage,
        download: usize,
    ) -> Result<(), (u32, u32)> {
        if self.m_fpCallback.is_none() {
            return Ok(());
        }
        let (size, ptr) = match storage {
            Storage::Var(v) => (
                v.data().map_or(0, <[AtomicU8]>::len),
                v.m_pData.load(Ordering::Relaxed),
            ),
            Storage::RamString(b) => (b.len().saturating_sub(1), b.as_ptr() as *mut c_void),
            _ => return Ok(()),
        };
        let mut p = ObdVStringDomain {
            m_DownloadSize: ObdSize::try_from(download).unwrap_or(ObdSize::MAX),
            m_ObjSize: ObdSize::try_from(size).unwrap_or(ObdSize::MAX),
            m_pData: ptr,
        };
        self.notify(
            handle,
            crate::od::event::WR_STRING_DOMAIN,
            sub,
            CbArg::StringDomain(&mut p),
        )?;
        if let Storage::Var(v) = storage {
            if p.m_pData != ptr || obd_size_len(p.m_ObjSize) != size {
                v.m_pData.store(p.m_pData, Ordering::Relaxed);
                v.m_Size.store(p.m_ObjSize, Ordering::Relaxed);
            }
        }
        Ok(())
    }

    /// Calls the entry's callback (if any) with `event`. `Err` carries the
    /// abort code the callback set (0x08000020 when it refused without one)
    /// and the `tCopKernel` it returned.
    pub fn notify(
        &self,
        handle: CallbackHandle,
        event: u8,
        sub: u8,
        arg: CbArg<'_>,
    ) -> Result<(), (u32, u32)> {
        let Some(cb) = self.m_fpCallback else {
            return Ok(());
        };
        let p = match arg {
            CbArg::None => core::ptr::null_mut(),
            CbArg::Data(d) => d.as_mut_ptr() as *mut c_void,
            CbArg::Size(s) => s as *mut ObdSize as *mut c_void,
            CbArg::StringDomain(d) => d as *mut ObdVStringDomain as *mut c_void,
        };
        let mut param = ObdCbParam {
            m_ObdEvent: event,
            m_wIndex: self.m_wIndex,
            m_bSubIndex: sub,
            m_pArg: p,
            m_dwAbortCode: 0,
        };
        // SAFETY: the callback is a C function of type tObdCallback that the
        // application registered in its objdict.h; `param` is valid for the
        // duration of the call and m_pArg points to live data of the kind the
        // event documents.
        let ret = unsafe { call_back!(cb, handle, &mut param) };
        if ret == 0 {
            Ok(())
        } else {
            let abort = if param.m_dwAbortCode != 0 {
                param.m_dwAbortCode
            } else {
                crate::error::SdoAbort::CannotStore.code()
            };
            Err((abort, ret))
        }
    }
}

impl ObdVarEntry {
    /// An empty entry (no variable attached).
    pub const fn new() -> ObdVarEntry {
        ObdVarEntry {
            m_pData: AtomicPtr::new(core::ptr::null_mut()),
            m_Size: AtomicObdSize::new(0),
            m_fpCallback: AtomicPtr::new(core::ptr::null_mut()),
            m_pArg: AtomicPtr::new(core::ptr::null_mut()),
        }
    }

    /// Attaches a Rust-owned variable.
    pub fn attach(&self, data: &'static [AtomicU8]) -> bool {
        let Ok(size) = ObdSize::try_from(data.len()) else {
            return false;
        };
        self.m_pData
            .store(data.as_ptr() as *mut c_void, Ordering::Relaxed);
        self.m_Size.store(size, Ordering::Relaxed);
        true
    }

    /// The attached variable, if the application defined one.
    pub fn data(&self) -> Option<&'static [AtomicU8]> {
        let p = self.m_pData.load(Ordering::Relaxed);
        if p.is_null() {
            return None;
        }
        // tObdSize is u8, u16 or u32 depending on the configuration.
        #[allow(clippy::unnecessary_fallible_conversions)]
        let n = usize::try_from(self.m_Size.load(Ordering::Relaxed)).unwrap_or(0);
        // SAFETY: the application attached (CcmDefineVarTab / attach) a
        // variable of m_Size bytes that outlives the stack; AtomicU8 has the
        // layout of u8.
        Some(unsafe { core::slice::from_raw_parts(p as *const AtomicU8, n) })
    }

    /// Sets the data size (domains whose length changed on write).
    pub fn set_size(&self, size: usize) {
        if let Ok(s) = ObdSize::try_from(size) {
            self.m_Size.store(s, Ordering::Relaxed);
        }
    }

    /// Calls the variable callback registered with the variable, if any.
    /// Out of line: the one call site of a variable callback, which the
    /// worst-case stack analysis resolves like an OBD callback
    /// (scripts/tms570/run.sh, docs/tms570.md).
    #[inline(never)]
    pub fn notify(&self, handle: CallbackHandle) -> u32 {
        let f = self.m_fpCallback.load(Ordering::Relaxed);
        if f.is_null() {
            return 0;
        }
        // SAFETY: a non-NULL m_fpCallback was stored by CcmDefineVarTab from
        // a tVarCallback function pointer of the application.
        let cb: VarCallback = unsafe { core::mem::transmute::<*mut c_void, VarCallback>(f) };
        // SAFETY: calling the application's callback with its own argument.
        unsafe { call_back!(cb, handle, self.m_pArg.load(Ordering::Relaxed)) }
    }
}

super::decl::default_is_new!(ObdVarEntry);

// ---------------------------------------------------------------------
// The pool of the dynamic OD
// ---------------------------------------------------------------------

/// The memory of the dynamic OD's pool and the code that lays the tables
/// out in it (raw pointers); the rest of the pool (its state, the layout)
/// is in [`crate::od::dynamic::pool`], the decisions in
/// [`crate::od::dynamic`].
mod pool {
    use core::cell::UnsafeCell;
    use core::ffi::c_void;
    use core::sync::atomic::{AtomicBool, AtomicU8, AtomicU32};

    use super::{ObdEntry, ObdSubEntry};
    use crate::error::CopKernel;
    use crate::od::Part;
    use crate::od::dcf::Container;
    use crate::od::dynamic::pool::{Layout, copy_entry, init_image};
    use crate::od::dynamic::{Blame, BuildInfo, Installed, Place, Plan, Target, image_overlaps_in};
    use crate::port::{CanPort, Ticks};

    /// The pool's bytes, zero from the start (a `static` in `.bss`), so that
    /// they can always be lent out as `&mut [u8]`.
    #[repr(C, align(8))]
    struct Mem<const N: usize>([u8; N]);

    /// Storage for the tables of one dynamic object dictionary (see
    /// [`crate::ffi::dynod`] for the layout). Declare it as a `static`; it is claimed by a
    /// build and given back by [`DynPool::destroy`] or [`DynPool::release`].
    ///
    /// ```
    /// use cop::od::dynamic::DynPool;
    /// static POOL: DynPool<4096> = DynPool::new();
    /// assert!(!POOL.is_in_use());
    /// ```
    pub struct DynPool<const N: usize> {
        mem: UnsafeCell<Mem<N>>,
        pub(in crate::od) claimed: AtomicBool,
        /// The last build's refusal: code (0 after a build that succeeded).
        pub(in crate::od) last_code: AtomicU32,
        /// Index << 8 | subindex of the entry it was about (0: none).
        pub(in crate::od) last_entry: AtomicU32,
        /// Byte offset of that entry in the container.
        pub(in crate::od) last_offset: AtomicU32,
    }

    // SAFETY: the memory is written only by the build that claimed the pool
    // (`claimed` is taken with compare-exchange) and read through the tables
    // afterwards; the stack API is single-threaded per instance.
    unsafe impl<const N: usize> Sync for DynPool<N> {}

    impl<const N: usize> Default for DynPool<N> {
        fn default() -> Self {
            Self::new()
        }
    }

    impl<const N: usize> DynPool<N> {
        /// An unused pool.
        pub const fn new() -> Self {
            DynPool {
                mem: UnsafeCell::new(Mem([0; N])),
                claimed: AtomicBool::new(false),
                last_code: AtomicU32::new(0),
                last_entry: AtomicU32::new(0),
                last_offset: AtomicU32::new(0),
            }
        }

        pub(in crate::od) fn base(&self) -> *mut u8 {
            self.mem.get() as *mut u8
        }

        #[allow(clippy::too_many_arguments)]
        pub(in crate::od) fn plan_and_fill<T: Target>(
            &'static self,
            claimed: bool,
            stack: &mut T,
            port: &mut impl CanPort,
            now: Ticks,
            container: &[u8],
            image: Option<&'static [AtomicU8]>,
            blame: &mut Option<Blame>,
        ) -> Result<BuildInfo, CopKernel> {
            let image_len = image.map_or(0, <[AtomicU8]>::len);
            let plan = if claimed {
                // SAFETY: the pool is claimed by this build, so nothing else
                // uses its memory, and no reference into it exists (a previous
                // build's tables were detached from their stack before the pool
                // was given back). Its N bytes are initialised (`Mem` starts
                // zeroed and is only ever written with bytes).
                let scratch = unsafe { core::slice::from_raw_parts_mut(self.base(), N) };
                let c = Container::parse_indexed(container, scratch).map_err(|e| e.kernel())?;
                // SAFETY: the index took the last `index_len()` bytes of the
                // pool; the bytes before it are not referred to any more (the
                // slice above is not used again).
                let notes =
                    unsafe { core::slice::from_raw_parts_mut(self.base(), N - c.index_len()) };
                Plan::new_blamed(c, stack.od(), image_len, notes, blame)?
            } else {
                let c = Container::parse(container).map_err(|e| e.kernel())?;
                Plan::new_blamed(c, stack.od(), image_len, &mut [], blame)?
            };
            let original = stack.od().part(Part::User);
            let layout = Layout::of::<T::RxChannel, T::TxChannel>(&plan, original.len())
                .ok_or(CopKernel::DynNoMemory)?;
            if layout.end > N {
                return Err(CopKernel::DynNoMemory);
            }
            if !claimed {
                return Err(CopKernel::NoFreeInstance);
            }
            // The index and the plan's notes lie at the end of the pool; the
            // tables and the snapshot are written before them, the copy of the
            // index segment over them at the very end. When the tables would
            // reach them, the build goes on without them.
            let index_at = N - plan.container().index_len() - plan.notes_len();
            let plan = if index_at < layout.copy_at {
                plan.without_index()
            } else {
                plan
            };
            self.fill(
                &plan, &layout, index_at, original, stack, port, now, image, blame,
            )
        }

        #[allow(clippy::too_many_arguments)]
        fn fill<T: Target>(
            &'static self,
            plan: &Plan<'_>,
            layout: &Layout,
            index_at: usize,
            original: &'static [ObdEntry],
            stack: &mut T,
            port: &mut impl CanPort,
            now: Ticks,
            image: Option<&'static [AtomicU8]>,
            blame: &mut Option<Blame>,
        ) -> Result<BuildInfo, CopKernel> {
            // The pool is claimed by this build, so nothing else writes it; the
            // only references into it are the container's index and the plan's
            // notes, at `index_at..N`, which is not below `copy_at` while the
            // plan uses them (checked by the caller). `layout.end <= N` was
            // checked, so every region is inside `mem`. Every byte of the
            // regions that is read later is written below first (tables, the
            // variables' initial values, the snapshot records).
            let base = self.base();
            let entries_ptr = base as *mut ObdEntry;
            // SAFETY: subs_at + subs * size <= end <= N (Layout::of).
            let subs_ptr = unsafe { base.add(layout.subs_at) } as *mut ObdSubEntry;
            // SAFETY: data_at <= end <= N.
            let mut data_ptr = unsafe { base.add(layout.data_at) };
            let data_end = layout.snap_at;

            let mut written_entries = 0usize;
            let mut written_subs = 0usize;
            let mut orig = original.iter().peekable();
            let mut put_entry = |e: ObdEntry| -> Result<(), CopKernel> {
                if written_entries >= layout.entries {
                    return Err(CopKernel::DynInvalidConfig);
                }
                // SAFETY: written_entries < entries; the region holds `entries`
                // properly aligned ObdEntry slots (offset 0 of an 8-aligned pool).
                unsafe { entries_ptr.add(written_entries).write(e) };
                written_entries += 1;
                Ok(())
            };
            for (index, subs) in plan.new_objects() {
                while let Some(o) = orig.next_if(|o| o.index() < index) {
                    put_entry(copy_entry(o))?;
                }
                let first = written_subs;
                for d in subs {
                    let d = d?;
                    if written_subs >= layout.subs {
                        return Err(CopKernel::DynInvalidConfig);
                    }
                    let current: *mut c_void = match d.place {
                        Place::Pool => {
                            let len = d.storage_len();
                            // SAFETY: data_ptr stays within data_at..snap_at:
                            // the plan counted `storage_len` for every pool
                            // variable into data_bytes (checked below).
                            let used = unsafe { data_ptr.offset_from(base) } as usize;
                            if used + len > data_end {
                                return Err(CopKernel::DynInvalidConfig);
                            }
                            // SAFETY: the range is inside the zeroed, claimed
                            // pool and no other reference to it exists.
                            let dst = unsafe { core::slice::from_raw_parts_mut(data_ptr, len) };
                            d.initial_bytes(dst)?;
                            let p = data_ptr as *mut c_void;
                            // SAFETY: stays within the region (checked above).
                            data_ptr = unsafe { data_ptr.add(len) };
                            p
                        }
                        Place::Image(off) => {
                            let img = image.ok_or(CopKernel::DynInvalidConfig)?;
                            let var = img
                                .get(off as usize..off as usize + d.storage_len())
                                .ok_or(CopKernel::DynNoMemory)?;
                            var.as_ptr() as *mut c_void
                        }
                    };
                    let e = ObdSubEntry {
                        m_bSubIndex: d.sub,
                        m_bType: d.typ.code(),
                        m_bAccess: d.access.0,
                        m_bKind: d.kind,
                        m_dwSize: d.size,
                        m_pDefault: core::ptr::null(),
                        m_pCurrent: current,
                    };
                    // SAFETY: written_subs < subs; the region holds `subs`
                    // aligned slots.
                    unsafe { subs_ptr.add(written_subs).write(e) };
                    written_subs += 1;
                }
                let count =
                    u8::try_from(written_subs - first).map_err(|_| CopKernel::DynInvalidConfig)?;
                put_entry(ObdEntry {
                    m_wIndex: index,
                    // SAFETY: `first` <= written_subs <= subs.
                    m_pSubIndex: unsafe { subs_ptr.add(first) },
                    m_bCount: count,
                    m_fpCallback: None,
                })?;
            }
            for o in orig {
                put_entry(copy_entry(o))?;
            }
            if written_entries != layout.entries || written_subs != layout.subs {
                return Err(CopKernel::DynInvalidConfig);
            }
            // SAFETY: snap_at..copy_at is initialised pool memory nobody else
            // refers to.
            let snapshot: &mut [u8] = unsafe {
                core::slice::from_raw_parts_mut(
                    base.add(layout.snap_at),
                    layout.copy_at - layout.snap_at,
                )
            };
            // SAFETY: every slot was written above; from now on the tables are
            // only read (until the pool is given back).
            let merged: &'static [ObdEntry] =
                unsafe { core::slice::from_raw_parts(entries_ptr, layout.entries) };
            // SAFETY: as above.
            let subs: &'static [ObdSubEntry] =
                unsafe { core::slice::from_raw_parts(subs_ptr, layout.subs) };

            if let Some(img) = image {
                // The bytes between the copy region's start and the index are
                // free until the copy is made (the last step).
                let free_end = if plan.container().is_indexed() {
                    index_at
                } else {
                    N
                };
                // SAFETY: copy_at..free_end lies inside the pool, after every
                // table and the snapshot and before the index; nothing refers
                // to it.
                let free = unsafe {
                    core::slice::from_raw_parts_mut(
                        base.add(layout.copy_at),
                        free_end.saturating_sub(layout.copy_at),
                    )
                };
                if image_overlaps_in(img, subs, free) {
                    return Err(CopKernel::DynInvalidConfig);
                }
            }
            let mut candidate = *stack.od();
            candidate
                .set_user_part(merged)
                .map_err(|_| CopKernel::DynInvalidConfig)?;
            plan.check_pdos_blamed(&candidate, blame)?;

            // The candidate is the stack's dictionary with the new user part,
            // already validated.
            *stack.od_mut() = candidate;
            let pooled = layout.rx_channels + layout.tx_channels > 0;
            if pooled {
                // SAFETY: rx_at is aligned for the RPDO channel type and tx_at
                // for the TPDO one; rx_at + rx_channels * its size <= tx_at and
                // tx_at + tx_channels * its size <= data_at <= N (Layout::of),
                // so the two regions do not overlap; they are claimed pool
                // memory nobody else refers to. Every slot is written before
                // the slices are made.
                let (rx, tx) = unsafe {
                    let rx_first = base.add(layout.rx_at) as *mut T::RxChannel;
                    for i in 0..layout.rx_channels {
                        rx_first.add(i).write(T::new_rx_channel());
                    }
                    let tx_first = base.add(layout.tx_at) as *mut T::TxChannel;
                    for i in 0..layout.tx_channels {
                        tx_first.add(i).write(T::new_tx_channel());
                    }
                    (
                        core::slice::from_raw_parts_mut(rx_first, layout.rx_channels),
                        core::slice::from_raw_parts_mut(tx_first, layout.tx_channels),
                    )
                };
                stack.attach_pooled(
                    (layout.rx_channels > 0).then_some(rx),
                    (layout.tx_channels > 0).then_some(tx),
                );
                stack.reload_configuration(port, now);
            }
            if let Err(e) = plan.apply_blamed(stack, snapshot, now, blame) {
                let _ = stack.od_mut().set_user_part(original);
                if pooled {
                    stack.detach_pooled(port);
                }
                stack.reload_configuration(port, now);
                return Err(e);
            }
            if let Some(img) = image {
                init_image(plan, img);
            }
            let info = BuildInfo {
                pi: plan.pi,
                new_indices: plan.new_indices,
                new_subs: plan.new_subs,
                pool_used: layout.end,
            };
            // The plan (and its index) is not used from here on: the copy of
            // the index segment, kept for the resets, takes the end of the
            // layout.
            let segment = plan.container().index_segment();
            // SAFETY: copy_at + segment.len() = end <= N; the source is the
            // caller's container, which does not overlap the pool; the index
            // that lay here is not read any more.
            let values: &'static [u8] = unsafe {
                let dst = base.add(layout.copy_at);
                core::ptr::copy_nonoverlapping(segment.as_ptr(), dst, segment.len());
                core::slice::from_raw_parts(dst, segment.len())
            };
            stack.set_dynamic_od(Some(Installed {
                values,
                original_user: original,
                pool: self.id(),
            }));
            stack.reload_configuration(port, now);
            Ok(info)
        }
    }
}

pub use pool::DynPool;
