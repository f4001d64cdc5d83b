//! Store / restore of the safety configuration (README "Store and restore"):
//! a sealed SRDO configuration (0x13FF CRCs, 0x13FE = 0xA5) saved,
//! restored by a reset node, running again without reconfiguration; an
//! image whose CRC does not match leaves the SRDOs stopped and the check
//! names the SRDO. Set-up: `tests/srdo_support.rs`.

#[path = "srdo_support.rs"]
mod support;

use cop::CopKernel;
use cop::ccm::NmtCommand;
use cop::event::NmtState;
use cop::sim::nvram::SimNvram;
use cop::store::{Driver, part};
use support::*;

fn with_storage(n: &mut Node) -> &'static SimNvram {
    let nv = SimNvram::leaked(4096, 4);
    n.stack.set_store_driver(Some(Driver(nv)), 0x0304);
    n.stack.init_store().unwrap();
    nv
}

#[test]
fn a_saved_srdo_configuration_runs_after_a_reset_without_reconfiguration() {
    let mut net = Net::preoperational();
    // Without a saved image a reset node loses the configuration.
    net.c.command(NmtCommand::ResetNode);
    net.settle();
    assert_eq!(net.c.read(0x13FE, 0), 0);
    // Configured again (a changed SCT), sealed, saved.
    with_storage(&mut net.c);
    net.c.write(0x1301, 2, 120, 2).unwrap();
    net.c.seal().unwrap();
    let crc = net.c.read(0x13FF, 1);
    net.c.stack.save_parameters(part::ALL_PARTS).unwrap();
    net.c.command(NmtCommand::ResetNode);
    net.settle();
    assert_eq!(net.c.state(), NmtState::PreOperational);
    assert_eq!(net.c.read(0x13FE, 0), 0xA5, "restored as stored");
    assert_eq!(net.c.read(0x13FF, 1), crc);
    assert_eq!(net.c.read(0x1301, 2), 120);
    net.start();
    assert!(net.c.stack.srdo().is_running());
    // CiA 304 decision: no store while OPERATIONAL.
    assert_eq!(
        net.c.stack.save_parameters(part::ALL_PARTS),
        Err(CopKernel::CcmStoreUnvalidState)
    );
}

#[test]
fn a_restored_configuration_that_fails_the_check_does_not_run() {
    let mut net = Net::preoperational();
    with_storage(&mut net.c);
    // 0x13FE = 0xA5 with a 0x13FF CRC that does not match (written past the
    // write rules, as a foreign tool or a changed firmware default would).
    let crc = net.c.read(0x13FF, 1);
    net.c
        .stack
        .od()
        .poke_uint(0x13FF, 1, u64::from(crc ^ 1))
        .unwrap();
    assert_eq!(net.c.read(0x13FE, 0), 0xA5);
    net.c.stack.save_parameters(part::ALL_PARTS).unwrap();
    net.c.command(NmtCommand::ResetNode);
    net.settle();
    assert_eq!(net.c.read(0x13FE, 0), 0xA5);
    assert_eq!(net.c.read(0x13FF, 1), crc ^ 1);
    net.c.command(NmtCommand::StartRemoteNode);
    assert_eq!(net.c.state(), NmtState::Operational);
    assert!(!net.c.stack.srdo().is_running());
    assert_eq!(
        net.c.stack.srdo().check_config(net.c.stack.od()),
        Err((CopKernel::SrdoCfgCrcError, 0x1301))
    );
}
