//! A CiA 304 safety sensor in Rust: node 1 sends E-stop state and a safe
//! speed limit in SRDO 1 every 20 ms, through the `embedded-can` adapter
//! (`cop::port::embedded::NbPort` over an `embedded_can::nb::Can` driver),
//! to an actuator (node 2) on the simulated bus.
//!
//! ```text
//! cargo run --example safety_sensor --features embedded-can
//! COP_SIM_PCAP=sensor.pcap cargo run --example safety_sensor --features embedded-can
//! ```
//! Exits with 1 unless the actuator took every pair with the values sent.

#[path = "safety_common/mod.rs"]
mod common;

use std::process::ExitCode;

use common::{Node, acknowledge, actuator_od, sensor_od, set_values, values};
use cop::event::Event;
use cop::sim::SimBus;

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("safety_sensor: {e}");
            ExitCode::from(1)
        }
    }
}

fn run() -> Result<(), String> {
    let bus = SimBus::new();
    let mut sensor = Node::new(&bus, sensor_od::od().map_err(|e| format!("{e:?}"))?, 1)?;
    let mut actuator = Node::new(&bus, actuator_od::od().map_err(|e| format!("{e:?}"))?, 2)?;
    sensor.start()?;
    actuator.start()?;

    let (mut sent, mut taken, mut errors) = (0u32, 0u32, 0u32);
    for ms in 1..=200u32 {
        bus.advance_ms(1);
        if ms % 20 == 0 {
            // the speed limit drops from 250 to 100 mm/s half way
            let speed = if ms <= 100 { 250 } else { 100 };
            set_values(&sensor_od::NORMAL, &sensor_od::INVERTED, 1, speed);
            sensor
                .send_srdo(|_, _| {})
                .map_err(|e| format!("CcmSendSrdo at {ms} ms: {e:?}"))?;
            sent += 1;
            println!("[{ms:3} ms] sensor   SRDO 1 sent: E-stop released, speed limit {speed} mm/s");
        }
        sensor.process(|_, _| {});
        actuator.process(|stack, e| {
            match e {
                Event::SrdoEvent(_) => {
                    taken += 1;
                    let (e_stop, speed) = values(&actuator_od::NORMAL);
                    let (e_inv, s_inv) = values(&actuator_od::INVERTED);
                    if e_inv != !e_stop || s_inv != !speed {
                        errors += 1;
                    }
                    println!("[{ms:3} ms] actuator SRDO 1 valid: E-stop {e_stop}, speed limit {speed} mm/s");
                }
                Event::SrdoError(idx, code) => {
                    errors += 1;
                    println!("[{ms:3} ms] actuator AppSrdoError({idx:#06X}, {code:?})");
                }
                _ => {}
            }
            acknowledge(stack, &e);
        });
    }
    let (e_stop, speed) = values(&actuator_od::NORMAL);
    println!(
        "result: {sent} pairs sent, {taken} taken, {errors} errors; actuator holds E-stop {e_stop}, speed limit {speed}"
    );
    if sent != 10 || taken != sent || errors != 0 || (e_stop, speed) != (1, 100) {
        return Err("the actuator did not take every pair as sent".into());
    }
    Ok(())
}
