//! The binary DCF container parser and the dynamic OD build
//! (`DynBuildOd`): arbitrary bytes as a container, applied to a device
//! with the reference dictionary. Checked on every input: no crash; a
//! refused container leaves every value of the dictionary and every PDO
//! COB-ID exactly as before (all or nothing); an accepted one can be
//! destroyed again, which removes the user part it created.
#![no_main]

use cop::ccm::Stack;
use cop::od::ByteOrder;
use cop::od::dynamic::DynPool;
use cop::sim::{SimBus, SimPort};
use libfuzzer_sys::fuzz_target;

static POOL: DynPool<4096> = DynPool::new();

/// Every (index, sub, value) of the dictionary, and the PDO COB-IDs.
fn snapshot(s: &Stack) -> Vec<(u16, u8, Vec<u8>)> {
    let od = s.od();
    let mut v = Vec::new();
    for e in od.entries() {
        for sub in 0..od.sub_count(e).min(256) {
            let Ok(obj) = od.find(e.index(), sub as u8) else {
                continue;
            };
            let mut b = [0u8; 512];
            let n = od.peek(&obj, ByteOrder::Native, &mut b).unwrap_or(0);
            v.push((e.index(), sub as u8, b[..n].to_vec()));
        }
    }
    for i in (0x1400u16..0x1404).chain(0x1800..0x1804) {
        let cob = s.pdo().cob_id(i).map(|c| c.raw()).unwrap_or(u32::MAX);
        v.push((i, 0xFF, cob.to_le_bytes().to_vec()));
    }
    v
}

fn device(bus: &SimBus) -> (SimPort, Stack) {
    let mut port = bus.attach(64);
    let mut s = Stack::new(cop::testod::dictionary(), 4).expect("reference dictionary");
    while s.drain(&mut port, bus.now()).is_some() {}
    s.connect().expect("connect");
    while s.drain(&mut port, bus.now()).is_some() {}
    (port, s)
}

fuzz_target!(|data: &[u8]| {
    let bus = SimBus::new();
    let (mut port, mut stack) = device(&bus);
    let before = snapshot(&stack);
    let user_before = stack.od().part(cop::od::Part::User).len();
    match POOL.build(&mut stack, &mut port, bus.now(), data, None) {
        Ok(_) => {
            POOL.destroy(&mut stack, &mut port, bus.now())
                .expect("destroy after a successful build");
            assert_eq!(
                stack.od().part(cop::od::Part::User).len(),
                user_before,
                "destroy left objects behind"
            );
        }
        Err(_) => {
            assert!(!POOL.is_in_use(), "a refused build kept the pool");
            assert_eq!(snapshot(&stack), before, "a refused container changed the dictionary");
        }
    }
    POOL.release(stack);
});
