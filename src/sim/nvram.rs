//! A simulated non-volatile memory for host tests: a RAM image that
//! survives a simulated restart (it outlives the stack), with fault hooks
//! (a power cut after N bytes or N driver calls, a failing driver, a bit
//! flip).

use std::sync::Mutex;

use crate::store::StorageDriver;
use crate::store::image::NvFault;

#[derive(Debug)]
struct Inner {
    mem: Vec<u8>,
    align: u32,
    cut: PowerCut,
    writes: usize,
}

/// RAM standing in for EEPROM / flash. Erased bytes read 0xFF.
#[derive(Debug)]
pub struct SimNvram(Mutex<Inner>);

impl SimNvram {
    /// `size` bytes, write granularity `align`.
    pub fn new(size: usize, align: u32) -> Self {
        SimNvram(Mutex::new(Inner {
            mem: vec![0xFF; size],
            align,
            cut: PowerCut::default(),
            writes: 0,
        }))
    }

    /// A memory that lives as long as the program (a `&'static` driver).
    /// Each one stays listed in a static, so a leak checker (Miri) sees it
    /// reachable rather than lost.
    pub fn leaked(size: usize, align: u32) -> &'static SimNvram {
        static ALL: Mutex<Vec<&'static SimNvram>> = Mutex::new(Vec::new());
        let nv: &'static SimNvram = Box::leak(Box::new(Self::new(size, align)));
        ALL.lock().unwrap_or_else(|e| e.into_inner()).push(nv);
        nv
    }

    fn inner(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Power fails after `n` more bytes erased or written.
    pub fn cut_after_bytes(&self, n: usize) {
        self.inner().cut.bytes = Some(n);
    }

    /// Power fails after `n` more driver calls.
    pub fn cut_after_calls(&self, n: usize) {
        self.inner().cut.calls = Some(n);
    }

    /// Power is back: no cut pending, the memory answers again.
    pub fn power_on(&self) {
        self.inner().cut = PowerCut::default();
    }

    /// Inverts bit `bit` of the byte at `offset`.
    pub fn flip(&self, offset: usize, bit: u8) {
        if let Some(b) = self.inner().mem.get_mut(offset) {
            *b ^= 1 << (bit & 7);
        }
    }

    /// Bytes erased or written so far.
    pub fn bytes_written(&self) -> usize {
        self.inner().writes
    }

    /// A copy of the memory.
    pub fn snapshot(&self) -> Vec<u8> {
        self.inner().mem.clone()
    }
}

/// When the power fails: after `bytes` more bytes erased or written, or
/// after `calls` more driver calls (`None`: no cut pending). From the cut
/// on, every call fails.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PowerCut {
    pub(crate) bytes: Option<usize>,
    pub(crate) calls: Option<usize>,
    dead: bool,
}

impl PowerCut {
    /// One driver call.
    pub(crate) fn call(&mut self) -> Result<(), NvFault> {
        if self.dead {
            return Err(NvFault);
        }
        Self::spend(&mut self.calls, &mut self.dead)
    }

    /// One byte erased or written.
    pub(crate) fn byte(&mut self) -> Result<(), NvFault> {
        Self::spend(&mut self.bytes, &mut self.dead)
    }

    fn spend(left: &mut Option<usize>, dead: &mut bool) -> Result<(), NvFault> {
        match left {
            Some(0) => {
                *dead = true;
                Err(NvFault)
            }
            Some(n) => {
                *n -= 1;
                Ok(())
            }
            None => Ok(()),
        }
    }
}

impl Inner {
    fn call(&mut self) -> Result<(), NvFault> {
        self.cut.call()
    }

    fn put(&mut self, at: usize, v: u8) -> Result<(), NvFault> {
        self.cut.byte()?;
        *self.mem.get_mut(at).ok_or(NvFault)? = v;
        self.writes += 1;
        Ok(())
    }
}

impl StorageDriver for SimNvram {
    fn size(&self) -> u32 {
        u32::try_from(self.inner().mem.len()).unwrap_or(u32::MAX)
    }
    fn align(&self) -> u32 {
        self.inner().align
    }
    fn read(&self, offset: u32, out: &mut [u8]) -> Result<(), NvFault> {
        let mut i = self.inner();
        i.call()?;
        let at = offset as usize;
        out.copy_from_slice(i.mem.get(at..at + out.len()).ok_or(NvFault)?);
        Ok(())
    }
    fn write(&self, offset: u32, data: &[u8]) -> Result<(), NvFault> {
        let mut i = self.inner();
        i.call()?;
        if offset % i.align != 0 || data.len() as u32 % i.align != 0 {
            return Err(NvFault);
        }
        for (k, &b) in data.iter().enumerate() {
            i.put(offset as usize + k, b)?;
        }
        Ok(())
    }
    fn erase(&self, offset: u32, len: u32) -> Result<(), NvFault> {
        let mut i = self.inner();
        i.call()?;
        for k in 0..len as usize {
            i.put(offset as usize + k, 0xFF)?;
        }
        Ok(())
    }
    fn commit(&self) -> Result<(), NvFault> {
        self.inner().call()
    }
}
