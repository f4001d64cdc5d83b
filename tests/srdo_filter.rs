//! With a driver that filters by identifier (`CDRV_USE_IDVALID`, which the
//! manual requires for SRDOs), the stack must ask for every COB-ID it
//! needs: also for SRDO COB-IDs configured after reset communication, e.g.
//! over SDO in PRE-OPERATIONAL (they are subscribed when the node enters
//! OPERATIONAL).

#[path = "srdo_support.rs"]
mod support;

use std::collections::BTreeSet;

use cop::ccm::{NmtCommand, Stack};
use cop::error::CopResult;
use cop::od::ByteOrder;
use cop::port::{CanFrame, CanId, CanPort, Priority, RxFrame};
use cop::sim::{SimBus, SimPort};

/// A port that receives only subscribed identifiers, like a driver with an
/// acceptance filter.
struct Filtering {
    inner: SimPort,
    ids: BTreeSet<u32>,
}

impl CanPort for Filtering {
    fn send(&mut self, f: &CanFrame, p: Priority) -> CopResult {
        self.inner.send(f, p)
    }
    fn receive(&mut self) -> Option<RxFrame> {
        while let Some(r) = self.inner.receive() {
            if self.ids.contains(&r.frame.id.raw()) {
                return Some(r);
            }
        }
        None
    }
    fn subscribe(&mut self, id: CanId, _: Priority) -> CopResult {
        self.ids.insert(id.raw());
        Ok(())
    }
    fn unsubscribe(&mut self, id: CanId) -> CopResult {
        self.ids.remove(&id.raw());
        Ok(())
    }
}

fn write(s: &mut Stack, index: u16, sub: u8, v: u32, len: usize, bus: &SimBus) {
    s.write_object(
        index,
        sub,
        ByteOrder::Wire,
        &v.to_le_bytes()[..len],
        bus.now(),
    )
    .unwrap();
}

// req: M-2.5.2-RECEIVE
#[test]
fn srdo_cob_ids_changed_in_preoperational_are_received() {
    let _guard = support::serial_guard();
    let bus = SimBus::new();
    let mut port = Filtering {
        inner: bus.attach(64),
        ids: BTreeSet::new(),
    };
    let mut s = Stack::new(support::consumer::od(), 2).unwrap();
    while s.drain(&mut port, bus.now()).is_some() {}
    s.connect().unwrap();
    while s.drain(&mut port, bus.now()).is_some() {}
    assert!(
        port.ids.contains(&0x101),
        "default COB-ID subscribed at reset"
    );
    // Reconfigure SRDO 1 to 0x111/0x112 (direction off first, as CiA 304
    // requires), then back to receive, new CRC, 0xA5.
    write(&mut s, 0x1301, 1, 0, 1, &bus);
    write(&mut s, 0x1301, 5, 0x111, 4, &bus);
    write(&mut s, 0x1301, 6, 0x112, 4, &bus);
    write(&mut s, 0x1301, 1, 2, 1, &bus);
    for idx in [0x1301u16, 0x1302] {
        let crc = s.srdo().calc_crc(s.od(), idx).unwrap();
        write(
            &mut s,
            0x13FF,
            (idx - 0x1300) as u8,
            u32::from(crc),
            2,
            &bus,
        );
    }
    #[cfg(feature = "srdo-static-mapping")]
    {
        // Static mapping: the variable fields are defined before 0xA5.
        let od = *s.od();
        s.srdo_mut()
            .static_define_var_fields(
                &od,
                0x1301,
                &support::consumer::NORMAL,
                &support::consumer::INVERTED,
            )
            .unwrap();
    }
    write(&mut s, 0x13FE, 0, 0xA5, 1, &bus);
    assert!(!port.ids.contains(&0x111));
    s.exec_command(NmtCommand::StartRemoteNode).unwrap();
    let now = bus.now();
    s.process(&mut port, now, |_, _| {});
    assert!(port.ids.contains(&0x111) && port.ids.contains(&0x112));
    // A valid pair on the new COB-IDs now reaches the SRDO module.
    bus.inject(CanFrame::new(CanId::std_masked(0x111), &[1, 0, 2, 0]));
    bus.inject(CanFrame::new(
        CanId::std_masked(0x112),
        &[0xFE, 0xFF, 0xFD, 0xFF],
    ));
    let mut events = Vec::new();
    let now = bus.now();
    s.process(&mut port, now, |_, e| events.push(e));
    assert!(
        events.contains(&cop::event::Event::SrdoEvent(0x1301)),
        "{events:?}"
    );
}
