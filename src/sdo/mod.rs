//! SDO server and client: CiA 301 SDO protocols.
pub(crate) mod block;
pub mod client;
pub mod server;
pub use client::SdoClient;
pub use server::{SdoServer, SdoServers};

use crate::error::{CopKernel, OdError, SdoAbort};
use crate::od::{Object, ObjectDictionary, Staged};
use crate::wire::pdo::{COB_EXTENDED, COB_INVALID, COB_NO_RTR, is_restricted};

/// First SDO parameter object (server 0x1200..=0x127F, client
/// 0x1280..=0x12FF).
pub const PARAMETER_FIRST: u16 = 0x1200;
/// Last SDO parameter object.
pub const PARAMETER_LAST: u16 = 0x12FF;
/// First SDO client parameter object.
pub const CLIENT_PARAMETER_FIRST: u16 = 0x1280;

/// The kernel code for an SDO parameter object `index` (sub 1 or 2) that
/// has no channel in this build: a server beyond `SDO_MAX_SERVER_IN_OBD`
/// (`kCopSdosNoFreeEntry`) or a client beyond `SDO_MAX_CLIENT_IN_OBD`
/// (`kCopSdocNoFreeEntry`); `None` for a parameter object with a channel
/// and for any other index. CiA 301 §7.5.2.33 / §7.5.2.34 number the
/// channels from 0x1200 and 0x1280.
pub const fn without_channel(index: u16) -> Option<CopKernel> {
    use crate::config::{SDO_MAX_CLIENT_IN_OBD, SDO_MAX_SERVER_IN_OBD};
    if index < PARAMETER_FIRST || index > PARAMETER_LAST {
        None
    } else if index < CLIENT_PARAMETER_FIRST {
        if ((index - PARAMETER_FIRST) as usize) < SDO_MAX_SERVER_IN_OBD {
            None
        } else {
            Some(CopKernel::SdosNoFreeEntry)
        }
    } else if ((index - CLIENT_PARAMETER_FIRST) as usize) < SDO_MAX_CLIENT_IN_OBD {
        None
    } else {
        Some(CopKernel::SdocNoFreeEntry)
    }
}

/// True when an SDO channel may use the COB-ID `v` (sub 1 or 2 of its
/// parameter object, CiA 301 §7.5.2.33 / §7.5.2.34): bit 31 set (the
/// channel does not exist), a 29-bit identifier (bit 29) where the driver
/// has 29-bit identifiers (`CDRV_CAN_SPEC` CAN20B; with CAN20A `tCanId` is
/// a WORD and the identifier would be cut), or an 11-bit identifier that
/// CiA 301 §7.3.5 does not reserve for another service.
/// The default SDO channels 0x581–0x5FF and 0x601–0x67F, reserved for SDO
/// itself, are allowed; NMT, the GFC and SRDO identifiers (0x001,
/// 0x101–0x180), NMT error control and the other reserved ranges are not,
/// so that no SDO frame can be sent on a safety identifier. Bit 30
/// (dynamic allocation) is left to the channel.
pub fn usable_cob_id(v: u32) -> bool {
    if v & COB_INVALID != 0 {
        return true;
    }
    if v & COB_EXTENDED != 0 {
        return crate::config::CDRV_CAN20B;
    }
    match u16::try_from(v & !COB_NO_RTR) {
        Ok(id) if id <= 0x7FF => !is_restricted(id) || matches!(id, 0x581..=0x5FF | 0x601..=0x67F),
        _ => false,
    }
}

/// Module hook: sub 1 and 2 of the SDO parameter objects take only a
/// [`usable_cob_id`], and while the channel's COB-ID is valid (bit 31
/// clear) a valid value may not change bits 0..29 (CiA 301 §7.5.2.33 /
/// §7.5.2.34, as for PDOs in §7.5.2.35): another identifier takes bit 31
/// first. Bit 30 (dynamic allocation) may change. An object without a
/// channel ([`without_channel`]) takes no valid value at all: the channel
/// would never answer. Each refusal is abort 0x06090030.
pub fn check_write(od: &ObjectDictionary, obj: &Object, value: &Staged) -> Result<(), OdError> {
    let cob =
        (PARAMETER_FIRST..=PARAMETER_LAST).contains(&obj.index()) && matches!(obj.sub(), 1 | 2);
    if !cob {
        return Ok(());
    }
    let Some(new) = value
        .as_u64()
        .map(|v| v as u32)
        .filter(|v| usable_cob_id(*v))
    else {
        return Err(OdError::VALUE_RANGE);
    };
    if new & COB_INVALID == 0 {
        if let Some(kernel) = without_channel(obj.index()) {
            return Err(OdError::new(kernel, SdoAbort::ValueRange));
        }
    }
    let cur = od
        .read_uint(obj.index(), obj.sub())
        .map_or(COB_INVALID, |v| v as u32);
    if moved_while_valid(cur, new) {
        return Err(OdError::VALUE_RANGE);
    }
    Ok(())
}

/// True when both COB-IDs are valid and differ in bits 0..29.
fn moved_while_valid(cur: u32, new: u32) -> bool {
    (cur | new) & COB_INVALID == 0 && (cur ^ new) & !COB_NO_RTR != 0
}

#[cfg(test)]
mod tests {
    use super::{moved_while_valid, usable_cob_id};

    #[test]
    fn parameter_objects_beyond_the_channels_have_none() {
        use super::without_channel;
        use crate::config::{SDO_MAX_CLIENT_IN_OBD, SDO_MAX_SERVER_IN_OBD};
        use crate::error::CopKernel;
        let servers = SDO_MAX_SERVER_IN_OBD as u16;
        let clients = SDO_MAX_CLIENT_IN_OBD as u16;
        assert_eq!(without_channel(0x1200), None);
        assert_eq!(without_channel(0x1200 + servers - 1), None);
        assert_eq!(
            without_channel(0x1200 + servers),
            Some(CopKernel::SdosNoFreeEntry)
        );
        assert_eq!(without_channel(0x127F), Some(CopKernel::SdosNoFreeEntry));
        assert_eq!(without_channel(0x1280), None);
        assert_eq!(without_channel(0x1280 + clients - 1), None);
        assert_eq!(
            without_channel(0x1280 + clients),
            Some(CopKernel::SdocNoFreeEntry)
        );
        assert_eq!(without_channel(0x12FF), Some(CopKernel::SdocNoFreeEntry));
        assert_eq!(without_channel(0x11FF), None);
        assert_eq!(without_channel(0x1300), None);
    }

    #[test]
    fn a_valid_cob_id_keeps_its_identifier() {
        // CiA 301 §7.5.2.33: bits 0..29 fixed while bit 31 is clear.
        assert!(moved_while_valid(0x641, 0x642));
        assert!(moved_while_valid(0x641, 0x2000_0641), "frame format");
        assert!(!moved_while_valid(0x641, 0x641));
        assert!(!moved_while_valid(0x641, 0x4000_0641), "bit 30 may change");
        // Switching bit 31 either way, and any change while invalid.
        assert!(!moved_while_valid(0x641, 0x8000_0642));
        assert!(!moved_while_valid(0x8000_0641, 0x642));
        assert!(!moved_while_valid(0x8000_0000, 0x8000_0642));
    }

    #[test]
    fn sdo_cob_ids_keep_off_the_identifiers_of_other_services() {
        // CiA 301 §7.3.5: the default SDO channels are SDO's own.
        for ok in [
            0x581, 0x5FF, 0x601, 0x67F, 0x580, 0x600, 0x080, 0x181, 0x6DF,
        ] {
            assert!(usable_cob_id(ok), "{ok:#x}");
        }
        // Bit 30 is the channel's; bit 31 (no channel) is not an
        // identifier of another service.
        for ok in [0x4000_0601, 0x8000_0101, 0x8000_0000] {
            assert!(usable_cob_id(ok), "{ok:#x}");
        }
        // 29-bit identifiers (bit 29) only where the driver's identifiers
        // have 29 bits (CDRV_CAN_SPEC CAN20B; with CAN20A tCanId is a WORD).
        for ext in [0x2000_0101, 0x2123_4603, 0x3FFF_FFFF] {
            assert_eq!(usable_cob_id(ext), crate::config::CDRV_CAN20B, "{ext:#x}");
        }
        // NMT, GFC and SRDO, NMT error control, the other reserved ranges,
        // and identifiers beyond 11 bits.
        for bad in [
            0x000, 0x001, 0x07F, 0x101, 0x180, 0x6E0, 0x6FF, 0x701, 0x77F, 0x780, 0x7FF,
        ] {
            assert!(!usable_cob_id(bad), "{bad:#x}");
            assert!(!usable_cob_id(0x4000_0000 | bad), "{bad:#x} with bit 30");
        }
        assert!(!usable_cob_id(0x800));
        assert!(!usable_cob_id(0x1000_0601));
    }
}
