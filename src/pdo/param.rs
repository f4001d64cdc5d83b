//! A PDO definition as the application gives it (`tPdoParam`,
//! `tPdoStaticParam`), in Rust terms; the stack writes it through the
//! dictionary ([`crate::ccm::Stack::define_pdo`]).

use core::sync::atomic::AtomicU8;

use super::Direction;

/// One PDO definition (`tPdoParam` of `CcmDefinePdoTab`); `None` fields
/// are not valid (their `kPdoValid*` flag is clear) and keep what the
/// dictionary holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PdoParam<'a> {
    /// Communication parameter index (0x1400+ or 0x1800+).
    pub commu_index: u16,
    /// `m_bPdoType`: must match the index range.
    pub direction: Direction,
    /// `m_bNodeID`: added to the identifier of `cob_id` (0: none).
    pub node_id: u8,
    /// COB-ID (`kPdoValidCanId`).
    pub cob_id: Option<u32>,
    /// Transmission type (`kPdoValidTxType`).
    pub tx_type: Option<u8>,
    /// Inhibit time in 100 µs (`kPdoValidInihibitTime`).
    pub inhibit_time: Option<u16>,
    /// Event timer in ms (`kPdoValidEventTime`).
    pub event_time: Option<u16>,
    /// Number of mapped objects (`kPdoValidNrOfEntries`).
    pub entry_count: Option<u8>,
    /// Mapping entries (`kPdoValidMappObjects`); entries beyond the count
    /// are ignored.
    pub entries: Option<&'a [u32]>,
    /// The application wants `Event::Pdo` for this PDO
    /// (`kPdoValidCallback` with or without a function).
    pub notify: Option<bool>,
}

impl PdoParam<'_> {
    /// A definition of `commu_index` that changes nothing.
    pub const fn new(commu_index: u16, direction: Direction) -> Self {
        PdoParam {
            commu_index,
            direction,
            node_id: 0,
            cob_id: None,
            tx_type: None,
            inhibit_time: None,
            event_time: None,
            entry_count: None,
            entries: None,
            notify: None,
        }
    }
}

/// One static PDO (`tPdoStaticParam` of `CcmDefineStaticPdoTab`): the
/// payload is a byte block of the application instead of a mapping.
#[derive(Clone, Copy, Debug)]
pub struct StaticPdoParam {
    /// Communication parameter index (0x1400+ or 0x1800+).
    pub commu_index: u16,
    /// COB-ID.
    pub cob_id: u32,
    /// Transmission type.
    pub tx_type: u8,
    /// Inhibit time in 100 µs.
    pub inhibit_time: u16,
    /// Event timer in ms.
    pub event_time: u16,
    /// The payload (`m_pVarData`, `m_bSize` bytes, at most 8).
    pub data: &'static [AtomicU8],
    /// The application wants `Event::Pdo` for this PDO.
    pub notify: bool,
}
