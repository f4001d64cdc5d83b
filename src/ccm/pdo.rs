//! The SYS TEC PDO and SYNC API as methods of the stack (`CcmDefinePdoTab`,
//! `CcmDefineStaticPdoTab`, `CcmSignalStaticPdo`, `CcmSignalCheckVar`,
//! `CcmSignalVar`, `CcmSendPdo`, `CcmInitSyncConsumer`,
//! `CcmConfigSyncConsumer`, the PDO critical section). Parameters are
//! written through [`Stack::write_object`], so they pass the same checks as
//! an SDO download.

use super::Stack;
use crate::error::{CopKernel, CopResult, OdError};
use crate::od::{ByteOrder, Storage};
use crate::pdo::{
    Direction, PDO_MAX_MAPPENTRIES, PdoIndex, PdoParam, Role, SYNC_COB_ID_INDEX, SYNC_WINDOW_INDEX,
    StaticPdoParam,
};
use crate::port::{CanPort, Ticks};
use crate::wire::pdo::{COB_EXTENDED, COB_ID_MASK, COB_INVALID, COB_NO_RTR};

fn kernel(e: OdError) -> CopKernel {
    e.kernel
}

/// The communication parameters a definition writes (`None`: keep).
struct Commu {
    cob: Option<u32>,
    tx_type: Option<u8>,
    inhibit: Option<u16>,
    event: Option<u16>,
}

impl Stack {
    fn write_u32(&mut self, index: u16, sub: u8, v: u32, now: Ticks) -> CopResult {
        let bytes = v.to_le_bytes();
        self.write_object(index, sub, ByteOrder::Wire, &bytes, now)
            .map_err(kernel)
    }

    fn write_u16(&mut self, index: u16, sub: u8, v: u16, now: Ticks) -> CopResult {
        let bytes = v.to_le_bytes();
        self.write_object(index, sub, ByteOrder::Wire, &bytes, now)
            .map_err(kernel)
    }

    fn write_u8(&mut self, index: u16, sub: u8, v: u8, now: Ticks) -> CopResult {
        self.write_object(index, sub, ByteOrder::Wire, &[v], now)
            .map_err(kernel)
    }

    fn pdo_index(&self, commu_index: u16, dir: Direction) -> CopResult<PdoIndex> {
        let p = PdoIndex::of(commu_index)
            .filter(|p| p.role == Role::Commu)
            .ok_or(CopKernel::PdoNotExist)?;
        if p.dir != dir {
            return Err(CopKernel::InvalidParam);
        }
        self.pdo()
            .covers(self.od(), commu_index)
            .ok_or(CopKernel::PdoNotExist)
    }

    /// Writes the communication parameters shared by both definition
    /// calls, the COB-ID last. Leaves the PDO invalid when a step fails.
    fn define_commu(
        &mut self,
        p: PdoIndex,
        c: Commu,
        mapping: impl FnOnce(&mut Stack) -> CopResult,
        now: Ticks,
    ) -> CopResult {
        let commu = p.commu();
        let current = crate::pdo::mapping::cob_id_of(self.od(), commu);
        // CiA 301 mapping procedure step 1: the PDO must not exist while
        // its parameters change.
        if current & COB_INVALID == 0 {
            self.write_u32(commu, 1, current | COB_INVALID, now)?;
        }
        if let Some(t) = c.tx_type {
            self.write_u8(commu, 2, t, now)?;
        }
        if let Some(i) = c.inhibit {
            self.write_u16(commu, 3, i, now)?;
        }
        if let Some(e) = c.event {
            self.write_u16(commu, 5, e, now)?;
        }
        mapping(self)?;
        let last = c.cob.unwrap_or(current);
        if last != current | COB_INVALID {
            self.write_u32(commu, 1, last, now)?;
        }
        Ok(())
    }

    /// `CcmDefinePdoTab` for one PDO: writes the valid parameters through
    /// the dictionary in the CiA 301 order (invalidate, communication
    /// parameters, mapping with sub 0 = 0 / entries / sub 0 = n, COB-ID
    /// last) and records the callback wish.
    ///
    /// `kCopPdoNotExist` for an index that is not a PDO of the dictionary,
    /// `kCopInvalidParam` when `direction` does not match the index,
    /// `kCopPdoLengthExceeded` for more entries than `PDO_MAX_MAPPENTRIES`,
    /// otherwise the code of the refused write (`kCopPdoErrorMapp`,
    /// `kCopPdoVarNotFound`, `kCopPdoGranularityMismatch`,
    /// `kCopInvalidParam` for a reserved transmission type or a restricted
    /// COB-ID, ...). After a refusal the PDO stays invalid.
    pub fn define_pdo(&mut self, param: &PdoParam<'_>, now: Ticks) -> CopResult {
        let p = self.pdo_index(param.commu_index, param.direction)?;
        let cob = param.cob_id.map(|c| add_node_id(c, param.node_id));
        let entries = param.entries;
        let count = param.entry_count;
        if count.is_some_and(|c| usize::from(c) > PDO_MAX_MAPPENTRIES) {
            return Err(CopKernel::PdoLengthExceeded);
        }
        let mapping = |s: &mut Stack| -> CopResult {
            if entries.is_none() && count.is_none() {
                return Ok(());
            }
            let mapp = p.mapp();
            if s.od().find_entry(mapp).is_none() {
                return Err(CopKernel::PdoNotExist);
            }
            let current = s.od().read_uint(mapp, 0).unwrap_or(0) as u8;
            let n = count.unwrap_or(current);
            s.write_u8(mapp, 0, 0, now)?;
            if let Some(list) = entries {
                let list = list
                    .get(..usize::from(n))
                    .ok_or(CopKernel::PdoLengthExceeded)?;
                for (i, raw) in list.iter().enumerate() {
                    let sub = u8::try_from(i + 1).map_err(|_| CopKernel::PdoLengthExceeded)?;
                    s.write_u32(mapp, sub, *raw, now)?;
                }
            }
            s.write_u8(mapp, 0, n, now)
        };
        let c = Commu {
            cob,
            tx_type: param.tx_type,
            inhibit: param.inhibit_time,
            event: param.event_time,
        };
        self.define_commu(p, c, mapping, now)?;
        if let Some(n) = param.notify {
            let parts = self.pdo_parts();
            parts
                .pdo
                .attach(parts.od, param.commu_index, Some(n), None)?;
        }
        Ok(())
    }

    /// `CcmDefineStaticPdoTab` for one PDO: writes the communication
    /// parameters and attaches the byte block that replaces the mapping.
    ///
    /// `kCopPdoNotExist` for an index that is not a PDO of the dictionary,
    /// `kCopPdoLengthExceeded` for a block longer than 8 bytes, otherwise
    /// the code of the refused write.
    pub fn define_static_pdo(&mut self, param: &StaticPdoParam, now: Ticks) -> CopResult {
        let p = PdoIndex::of(param.commu_index)
            .filter(|p| p.role == Role::Commu)
            .ok_or(CopKernel::PdoNotExist)?;
        let p = self.pdo_index(param.commu_index, p.dir)?;
        if param.data.len() > 8 {
            return Err(CopKernel::PdoLengthExceeded);
        }
        let data = param.data;
        let commu = param.commu_index;
        // The block is attached before the COB-ID makes the PDO valid, so
        // that the PDO never runs with the dictionary mapping by mistake.
        let attach = move |s: &mut Stack| -> CopResult {
            let parts = s.pdo_parts();
            parts
                .pdo
                .attach(parts.od, commu, Some(param.notify), Some(Some(data)))
        };
        let c = Commu {
            cob: Some(param.cob_id),
            tx_type: Some(param.tx_type),
            inhibit: Some(param.inhibit_time),
            event: Some(param.event_time),
        };
        self.define_commu(p, c, attach, now)
    }

    /// `CcmSignalStaticPdo`: an application event for a TPDO (sent in the
    /// next cycle for types 254/255, with the next SYNC for type 0).
    /// `kCopPdoNotExist` when `commu_index` is not a TPDO of the dictionary.
    pub fn signal_pdo(&mut self, commu_index: u16) -> CopResult {
        self.pdo_parts().pdo.signal(commu_index)
    }

    /// `CcmSignalCheckVar`: the next cycle compares every event-driven and
    /// type 0 TPDO with the data it sent last and signals those that
    /// changed.
    pub fn signal_check_var(&mut self) {
        self.pdo_parts().pdo.signal_check_var();
    }

    /// `CcmSignalVar` by dictionary address: signals every valid TPDO that
    /// maps `index`/`sub`. `kCopPdoVarNotFound` when none does.
    pub fn signal_object(&mut self, index: u16, sub: u8) -> CopResult {
        let parts = self.pdo_parts();
        parts
            .pdo
            .signal_where(parts.od, |o| o.index() == index && o.sub() == sub)
    }

    /// `CcmSignalVar` by variable address: signals every valid TPDO that
    /// maps an object stored at `addr` (a RAM variable or an attached
    /// USERDEF variable). `kCopPdoVarNotFound` when none does.
    pub fn signal_var_at(&mut self, addr: usize) -> CopResult {
        let parts = self.pdo_parts();
        parts.pdo.signal_where(parts.od, |o| match o.storage() {
            Ok(Storage::Ram(m)) => m.as_ptr() as usize == addr,
            Ok(Storage::Var(v)) => v.data().is_some_and(|d| d.as_ptr() as usize == addr),
            _ => false,
        })
    }

    /// `CcmSendPdo`: samples and sends a TPDO now regardless of its
    /// transmission type and timers (see [`super::Pdo::send_now`] for the
    /// codes).
    pub fn send_pdo(&mut self, port: &mut impl CanPort, commu_index: u16, now: Ticks) -> CopResult {
        let parts = self.pdo_parts();
        parts
            .pdo
            .send_now(parts.od, parts.state, port, commu_index, now, parts.queue)
    }

    /// `CcmInitSyncConsumer`: (re)reads 0x1005–0x1007. The consumer is
    /// active from the start; this call exists for source compatibility.
    pub fn init_sync_consumer(&mut self) -> CopResult {
        let parts = self.pdo_parts();
        parts.pdo.reload_sync(parts.od);
        Ok(())
    }

    /// `CcmConfigSyncConsumer`: sets the SYNC COB-ID and the synchronous
    /// window (µs), through 0x1005 / 0x1007 where the dictionary has them.
    /// `kCopInvalidParam` for a COB-ID this consumer cannot use, and for
    /// bit 30: making this node the SYNC producer is
    /// `CcmConfigSyncProducer`'s job.
    pub fn config_sync_consumer(&mut self, cob_id: u32, window_us: u32, now: Ticks) -> CopResult {
        if cob_id & COB_NO_RTR != 0 {
            return Err(CopKernel::InvalidParam);
        }
        let has_cob = self.od().find_entry(SYNC_COB_ID_INDEX).is_some();
        let has_window = self.od().find_entry(SYNC_WINDOW_INDEX).is_some();
        if has_cob {
            self.write_u32(SYNC_COB_ID_INDEX, 0, cob_id, now)?;
        }
        if has_window {
            self.write_u32(SYNC_WINDOW_INDEX, 0, window_us, now)?;
        }
        let parts = self.pdo_parts();
        if !has_cob || !has_window {
            let cob = if has_cob {
                parts
                    .od
                    .read_uint(SYNC_COB_ID_INDEX, 0)
                    .map_or(cob_id, |v| v as u32)
            } else {
                cob_id
            };
            parts.pdo.set_sync(cob, window_us)?;
        }
        Ok(())
    }

    /// A SYNC this node sent itself (the controller does not receive it):
    /// the PDO module reacts as to a received one, in OPERATIONAL.
    pub(crate) fn own_sync(&mut self, at: Ticks) {
        let parts = self.pdo_parts();
        if parts.state == crate::event::NmtState::Operational {
            parts.pdo.on_sync(at);
        }
    }

    /// `CcmEnterCriticalSectionPdoProcess`.
    pub fn enter_critical_pdo(&mut self) {
        self.pdo_parts().pdo.enter_critical();
    }

    /// `CcmLeaveCriticalSectionPdoProcess`.
    pub fn leave_critical_pdo(&mut self) {
        self.pdo_parts().pdo.leave_critical();
    }
}

/// `m_bNodeID` is added to the identifier bits of a base identifier (its
/// node-ID bits 0..6 are 0, as 0x180 in the predefined connection set);
/// an identifier that already carries a node-ID (0x181 with node 1, as
/// master applications fill their PDO tables) is used as it is. The flag
/// bits stay.
fn add_node_id(cob: u32, node: u8) -> u32 {
    if node == 0 || cob & 0x7F != 0 {
        return cob;
    }
    let mask = if cob & COB_EXTENDED != 0 {
        COB_ID_MASK
    } else {
        0x7FF
    };
    let id = (cob & mask).wrapping_add(u32::from(node)) & mask;
    (cob & !mask) | id
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn node_id_goes_into_the_identifier_bits() {
        assert_eq!(add_node_id(0x8000_0180, 0), 0x8000_0180);
        assert_eq!(add_node_id(0x8000_0180, 5), 0x8000_0185);
        assert_eq!(add_node_id(0x4000_0200, 0x7F), 0x4000_027F);
        assert_eq!(add_node_id(0x2000_1000, 1), 0x2000_1001);
        // Already the full identifier: kept.
        assert_eq!(add_node_id(0x181, 1), 0x181);
        assert_eq!(add_node_id(0x4000_0283, 3), 0x4000_0283);
    }
}
