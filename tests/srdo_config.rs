//! The write rules of the SRDO objects over `Stack::write_object` (the
//! same hooks as an SDO download) and the configuration check when 0xA5 is
//! written to 0x13FE or `CcmCheckSrdoConfig` is called.
//! Set-up: `tests/srdo_support.rs`.

#[path = "srdo_support.rs"]
mod support;

use cop::error::{OdError, SdoAbort};
use cop::{CopKernel, ccm::NmtCommand};
use support::*;

/// One object write: (index, subindex, value, length).
type Write = (u16, u8, u32, usize);

fn refused(kernel: CopKernel, abort: u32) -> Result<(), OdError> {
    Err(OdError { kernel, abort })
}

/// Writes every CRC again and declares the configuration valid.
fn reseal(n: &mut Node) -> Result<(), OdError> {
    n.seal()
}

// req: SB-2-OPERATIONAL-WRITE
#[test]
fn every_write_is_refused_while_operational() {
    let mut net = Net::operational();
    for (index, sub, v, len) in [
        (0x1300u16, 0u8, 1u32, 1usize),
        (0x1301, 1, 0, 1),
        (0x1301, 2, 30, 2),
        (0x13FE, 0, 0, 1),
        (0x13FE, 0, 0xA5, 1),
        (0x13FF, 1, 0, 2),
    ] {
        assert_eq!(
            net.p.write(index, sub, v, len),
            refused(CopKernel::SrdoNmtError, 0x0800_0022),
            "{index:#x} sub {sub}"
        );
    }
    assert_eq!(
        net.p.read(0x13FE, 0),
        0xA5,
        "a refused write changes nothing"
    );
    assert_eq!(net.p.read(0x1301, 2), 25);
}

// req: SB-2-INVALIDATE, M-1.2-CFGVALID
#[test]
fn accepted_safety_write_invalidates_the_configuration() {
    let mut net = Net::preoperational();
    assert_eq!(net.p.read(0x13FE, 0), 0xA5);
    net.p.write(0x1301, 3, 15, 1).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0, "0x1301+n");
    reseal(&mut net.p).unwrap();
    net.p.write(0x13FF, 2, 0x1234, 2).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0, "0x13FF");
    reseal(&mut net.p).unwrap();
    // The GFC parameter is not a safety parameter.
    net.p.write(0x1300, 0, 1, 1).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0xA5);
}

// req: SB-2-OPERATIONAL-WRITE
#[test]
fn refused_writes_change_nothing() {
    let mut net = Net::preoperational();
    let cases = [
        // Direction values above 2 (manual table 2: reserved).
        (
            0x1301u16,
            1u8,
            3u32,
            1usize,
            CopKernel::ObdValueToHigh,
            0x0609_0030u32,
        ),
        // SCT / SRVT 0 while the SRDO is active.
        (0x1301, 2, 0, 2, CopKernel::SrdoCfgTimingError, 0x0609_0030),
        (0x1301, 3, 0, 1, CopKernel::SrdoCfgTimingError, 0x0609_0030),
        // COB-IDs only while direction is 0 (manual 1.1.1).
        (0x1301, 5, 0x103, 4, CopKernel::SrdoInvalidCfg, 0x0609_0030),
        (0x1301, 6, 0x104, 4, CopKernel::SrdoInvalidCfg, 0x0609_0030),
        // GFC parameter 0 or 1 (manual table 6).
        (0x1300, 0, 2, 1, CopKernel::ObdValueToHigh, 0x0609_0030),
    ];
    for (index, sub, v, len, kernel, abort) in cases {
        let before = net.p.read(index, sub);
        assert_eq!(
            net.p.write(index, sub, v, len),
            refused(kernel, abort),
            "{index:#x} sub {sub} = {v:#x}"
        );
        assert_eq!(net.p.read(index, sub), before);
        assert_eq!(net.p.read(0x13FE, 0), 0xA5, "0x13FE untouched");
    }
    // With direction 0 the COB-IDs may change, each within its own rule.
    net.p.write(0x1301, 1, 0, 1).unwrap();
    assert_eq!(
        net.p.write(0x1301, 5, 0x102, 4),
        refused(CopKernel::SrdoCfgIdError, 0x0609_0030),
        "COB-ID 1 must be odd"
    );
    assert_eq!(
        net.p.write(0x1301, 6, 0x8000_0104, 4),
        refused(CopKernel::SrdoCfgIdError, 0x0609_0030),
        "bits 31..11 reserved"
    );
    assert_eq!(
        net.p.write(0x1301, 5, 0x181, 4),
        refused(CopKernel::SrdoCfgIdError, 0x0609_0030),
        "above 0x180"
    );
    // CiA 304: COB-ID 2 is even, 0x102..=0x180 (0x100 is even, below).
    assert_eq!(
        net.p.write(0x1301, 6, 0x100, 4),
        refused(CopKernel::SrdoCfgIdError, 0x0609_0030),
        "below 0x102"
    );
    net.p.write(0x1301, 6, 0x180, 4).unwrap();
    net.p.write(0x1301, 5, 0x17F, 4).unwrap();
    net.p.write(0x1301, 5, 0x103, 4).unwrap();
    net.p.write(0x1301, 6, 0x104, 4).unwrap();
    assert_eq!(net.p.read(0x1301, 5), 0x103);
}

/// SAFETY_BEHAVIOUR.md section 2 and manual 1.1.1 restrict *changes* of
/// the COB-IDs and the mapping to direction 0: a write of the value in
/// force is no change and is accepted, and 0x13FE still drops to 0 as for
/// every safety write.
// req: SB-2-IDENTICAL
#[test]
fn a_write_of_the_value_in_force_is_accepted_while_active() {
    let mut net = Net::preoperational();
    assert_eq!(net.p.read(0x1301, 1), 1, "SRDO 1 transmits");
    let same: Vec<Write> = [(0x1301u16, 5u8, 4usize), (0x1301, 6, 4)]
        .into_iter()
        .chain(if cfg!(feature = "srdo-static-mapping") {
            vec![]
        } else {
            vec![(0x1381, 0, 1), (0x1381, 1, 4), (0x1381, 4, 4)]
        })
        .map(|(index, sub, len)| (index, sub, net.p.read(index, sub), len))
        .collect();
    for (index, sub, v, len) in same {
        assert_eq!(
            net.p.write(index, sub, v, len),
            Ok(()),
            "{index:#x} sub {sub} = {v:#x} again"
        );
        assert_eq!(net.p.read(index, sub), v);
        assert_eq!(net.p.read(0x13FE, 0), 0, "{index:#x} sub {sub}");
        reseal(&mut net.p).unwrap();
    }
    // Another value is still a change and still refused.
    let cob1 = net.p.read(0x1301, 5);
    assert_eq!(
        net.p.write(0x1301, 5, cob1 + 2, 4),
        refused(CopKernel::SrdoInvalidCfg, 0x0609_0030)
    );
    assert_eq!(net.p.read(0x13FE, 0), 0xA5);
    // The configuration sealed after the identical writes runs (`start`
    // checks that both nodes' SRDOs run).
    net.start();
}

// req: SB-1-TTYPE
#[test]
fn transmission_type_is_constant_254() {
    let mut net = Net::preoperational();
    assert_eq!(net.p.read(0x1301, 4), 254);
    assert_eq!(net.p.read(0x1301, 0), 6);
    assert_eq!(
        net.p.write(0x1301, 4, 254, 1).map_err(|e| e.abort),
        Err(SdoAbort::WriteReadOnly.code())
    );
}

// req: M-1.2-CFGVALID
#[test]
fn config_valid_runs_the_check_and_keeps_its_value_on_failure() {
    let mut net = Net::preoperational();
    net.p.write(0x1301, 2, 30, 2).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0);
    // The CRC in 0x13FF no longer matches.
    assert_eq!(
        net.p.write(0x13FE, 0, 0xA5, 1),
        refused(CopKernel::SrdoCfgCrcError, 0x0800_0020)
    );
    assert_eq!(net.p.read(0x13FE, 0), 0, "0x13FE stays invalid");
    let od = *net.p.stack.od();
    assert_eq!(
        net.p.stack.srdo().check_config(&od),
        Err((CopKernel::SrdoCfgCrcError, 0x1301))
    );
    // Another value than 0xA5 is stored without a check.
    net.p.write(0x13FE, 0, 0x5A, 1).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0x5A);
    reseal(&mut net.p).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0xA5);
    assert_eq!(net.p.stack.srdo().check_config(&od), Ok(()));
}

/// Makes a change through writes (direction 0 first where needed), writes
/// the CRCs and returns what writing 0xA5 gives.
fn check_after(n: &mut Node, writes: &[Write]) -> Result<(), OdError> {
    for &(index, sub, v, len) in writes {
        n.write(index, sub, v, len)
            .unwrap_or_else(|e| panic!("write {index:#x}/{sub} = {v:#x}: {e:?}"));
    }
    reseal(n)
}

// req: M-2.8.2-CHECK, SB-2-ORDER
#[test]
fn check_codes_over_the_write_path() {
    let cases: Vec<(Vec<Write>, CopKernel, u16)> = vec![
        // Timing: SRVT above SCT for a receive SRDO (consumer view below),
        // SCT 0 set while disabled, then enabled.
        (
            vec![(0x1301, 1, 0, 1), (0x1301, 2, 0, 2), (0x1301, 1, 1, 1)],
            CopKernel::SrdoCfgTimingError,
            0x1301,
        ),
        // COB-ID 2 not COB-ID 1 + 1.
        (
            vec![(0x1301, 1, 0, 1), (0x1301, 6, 0x106, 4), (0x1301, 1, 1, 1)],
            CopKernel::SrdoCfgIdError,
            0x1301,
        ),
        // SRDO 2 switched on with the COB-IDs of SRDO 1.
        (
            vec![
                (0x1302, 5, 0x101, 4),
                (0x1302, 6, 0x102, 4),
                (0x1302, 1, 1, 1),
            ],
            CopKernel::SrdoCanIdAlreadyInUse,
            0x1302,
        ),
    ];
    for (writes, code, idx) in cases {
        let mut net = Net::preoperational();
        assert_eq!(
            check_after(&mut net.p, &writes),
            refused(code, 0x0800_0020),
            "{writes:x?}"
        );
        assert_eq!(net.p.read(0x13FE, 0), 0);
        let od = *net.p.stack.od();
        assert_eq!(net.p.stack.srdo().check_config(&od), Err((code, idx)));
    }
    // Receive SRDO: SRVT may not exceed SCT.
    let mut net = Net::preoperational();
    assert_eq!(
        check_after(&mut net.c, &[(0x1301, 3, 26, 1)]),
        refused(CopKernel::SrdoCfgTimingError, 0x0800_0020)
    );
}

/// Switches SRDO 1 off (direction 0), writes `mapping`, switches it on
/// again as a transmit SRDO and returns what [`check_after`] gives.
#[cfg(not(feature = "srdo-static-mapping"))]
fn remap(n: &mut Node, mapping: &[Write]) -> Result<(), OdError> {
    n.write(0x1301, 1, 0, 1).unwrap();
    let mut writes = mapping.to_vec();
    writes.push((0x1301, 1, 1, 1));
    check_after(n, &writes)
}

#[cfg(not(feature = "srdo-static-mapping"))]
// req: SB-2-MAPPING
#[test]
fn mapping_rules_over_the_write_path() {
    let mut net = Net::preoperational();
    // Mapping only while direction is 0.
    assert_eq!(
        net.p.write(0x1381, 0, 2, 1),
        refused(CopKernel::SrdoInvalidCfg, 0x0609_0030)
    );
    assert_eq!(net.p.read(0x13FE, 0), 0xA5);
    net.p.write(0x1301, 1, 0, 1).unwrap();
    // Each mapping write is checked at once (manual 2.5), with the CiA 301
    // abort naming the reason (CiA 301 table 22); nothing changes.
    let mapp_err = CopKernel::SrdoErrorMapp;
    let too_many = cop::config::SRDO_MAX_MAPPENTRIES as u32 + 1;
    let cases: [(Write, CopKernel, u32); 6] = [
        // More entries than SRDO_MAX_MAPPENTRIES.
        ((0x1381, 0, too_many, 1), mapp_err, 0x0604_0042),
        // An odd number of entries.
        ((0x1381, 0, 3, 1), mapp_err, 0x0604_0043),
        // An object that does not exist, a subindex that does not.
        ((0x1381, 1, 0x3000_0110, 4), mapp_err, 0x0602_0000),
        ((0x1381, 1, 0x6202_0110, 4), mapp_err, 0x0602_0000),
        ((0x1381, 1, 0x6200_0210, 4), mapp_err, 0x0609_0011),
        // An object that cannot be mapped (SCT).
        ((0x1381, 1, 0x1301_0210, 4), mapp_err, 0x0604_0041),
    ];
    for ((index, sub, v, len), kernel, abort) in cases {
        let before = net.p.read(index, sub);
        assert_eq!(
            net.p.write(index, sub, v, len),
            refused(kernel, abort),
            "{index:#x} sub {sub} = {v:#x}"
        );
        assert_eq!(net.p.read(index, sub), before);
    }
    // Five pairs of 16 bits: 10 bytes do not fit a frame; the count that
    // would enable them is refused (0x06040042).
    if cop::config::SRDO_MAX_MAPPENTRIES >= 10 {
        let mut w = vec![(0x1381u16, 0u8, 0u32, 1usize)];
        for pair in 0..5u8 {
            w.push((0x1381, 2 * pair + 1, 0x6200_0110, 4));
            w.push((0x1381, 2 * pair + 2, 0x6300_0110, 4));
        }
        for &(index, sub, v, len) in &w {
            net.p.write(index, sub, v, len).unwrap();
        }
        assert_eq!(
            net.p.write(0x1381, 0, 10, 1),
            refused(CopKernel::SrdoLengthExceeded, 0x0604_0042)
        );
        assert_eq!(net.p.read(0x1381, 0), 0);
    }
    // The full check still runs at 0xA5: an empty mapping of an active
    // SRDO passes each write and fails there.
    assert_eq!(
        check_after(&mut net.p, &[(0x1381, 0, 0, 1), (0x1301, 1, 1, 1)]),
        refused(CopKernel::SrdoErrorMapp, 0x0800_0020)
    );
    // Back to the original mapping: valid again.
    assert_eq!(
        remap(
            &mut net.p,
            &[
                (0x1381, 0, 0, 1),
                (0x1381, 1, 0x6200_0110, 4),
                (0x1381, 2, 0x6300_0110, 4),
                (0x1381, 3, 0x6201_0110, 4),
                (0x1381, 4, 0x6301_0110, 4),
                (0x1381, 0, 4, 1),
            ]
        ),
        Ok(())
    );
    // The parameters as the application reads them (CcmGetSrdoParam).
    let od = *net.p.stack.od();
    let p = net.p.stack.srdo().commu_param(&od, 0x1301).unwrap();
    assert_eq!((p.direction, p.sct_ms), (1, 25));
    let m = net.p.stack.srdo().mapp_param(&od, 0x1301).unwrap();
    assert_eq!(m.count, 4);
    assert!(std::ptr::eq(
        m.vars[0].unwrap().as_ptr(),
        producer::NORMAL.as_ptr()
    ));
    assert!(std::ptr::eq(
        m.vars[1].unwrap().as_ptr(),
        producer::INVERTED.as_ptr()
    ));
}

// req: SB-2-RUN-ONLY-VALID
#[test]
fn invalid_configuration_does_not_run_when_operational() {
    let mut net = Net::preoperational();
    net.c.write(0x1301, 2, 30, 2).unwrap();
    net.c.command(NmtCommand::StartRemoteNode);
    assert!(!net.c.stack.srdo().is_running());
    net.inject(0x101, &[1, 0, 2, 0]);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    net.wait_ms(100);
    assert!(no_pm(&net.c.cycle()).is_empty(), "no SRDO events at all");
    assert_eq!(net.consumer_values(), [0, 0, 0, 0]);
}

// req: M-2.8.8-CALCCRC
#[test]
fn calc_crc_and_mapped_len_through_the_stack() {
    let net = Net::preoperational();
    let od = *net.p.stack.od();
    let s = net.p.stack.srdo();
    assert_eq!(s.mapped_len(&od, 0x1301), Ok(4));
    assert_eq!(s.mapped_len(&od, 0x1302), Ok(2));
    assert_eq!(s.calc_crc(&od, 0x1303), Err(CopKernel::SrdoNotExist));
    // The CRC written by seal() is the one the check compares.
    assert_eq!(
        s.calc_crc(&od, 0x1301).map(u32::from),
        Ok(net.p.read(0x13FF, 1))
    );
}
