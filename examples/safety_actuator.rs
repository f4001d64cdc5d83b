//! A CiA 304 safety actuator in Rust: node 2 drives a safe output from
//! SRDO 1 of a sensor (node 1), both through the `embedded-can` adapter
//! (`cop::port::embedded::NbPort`) on the simulated bus. The output goes on
//! with a valid pair whose E-stop says "released", off at once with the
//! global fail-safe command (GFC) or an E-stop, and off with any SRDO
//! error; the sensor falls silent at the end and the SCT finds it.
//!
//! ```text
//! cargo run --example safety_actuator --features embedded-can
//! COP_SIM_PCAP=actuator.pcap cargo run --example safety_actuator --features embedded-can
//! ```
//! Exits with 1 unless the output followed that story.

#[path = "safety_common/mod.rs"]
mod common;

use std::process::ExitCode;

use common::{Node, SCT_MS, acknowledge, actuator_od, sensor_od, set_values, values};
use cop::CopKernel;
use cop::event::Event;
use cop::sim::SimBus;

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("safety_actuator: {e}");
            ExitCode::from(1)
        }
    }
}

/// What the actuator's output did, in order.
#[derive(Debug, PartialEq, Eq)]
enum Output {
    On(u32),
    OffGfc(u32),
    OffEStop(u32),
    OffError(u32, CopKernel),
}

fn run() -> Result<(), String> {
    let bus = SimBus::new();
    let mut sensor = Node::new(&bus, sensor_od::od().map_err(|e| format!("{e:?}"))?, 1)?;
    let mut actuator = Node::new(&bus, actuator_od::od().map_err(|e| format!("{e:?}"))?, 2)?;
    sensor.start()?;
    actuator.start()?;

    let mut on = false;
    let mut story = Vec::new();
    for ms in 1..=260u32 {
        bus.advance_ms(1);
        // E-stop pressed from 100 to 139 ms; the sensor stops at 200 ms
        let pressed = (100..140).contains(&ms);
        if ms == 100 {
            sensor
                .send_gfc()
                .map_err(|e| format!("CcmSendGfc: {e:?}"))?;
            println!("[{ms:3} ms] sensor   E-stop pressed: GFC");
        }
        if ms <= 200 && (ms % 20 == 0 || ms == 100) {
            set_values(
                &sensor_od::NORMAL,
                &sensor_od::INVERTED,
                u16::from(!pressed),
                250,
            );
            sensor
                .send_srdo(|_, _| {})
                .map_err(|e| format!("CcmSendSrdo: {e:?}"))?;
        }
        sensor.process(|_, _| {});
        actuator.process(|stack, e| {
            let off = |on: &mut bool, story: &mut Vec<Output>, why: Output| {
                if *on {
                    println!("[{ms:3} ms] actuator >>> SAFE OUTPUT OFF ({why:?})");
                    story.push(why);
                }
                *on = false;
            };
            match e {
                Event::Gfc => off(&mut on, &mut story, Output::OffGfc(ms)),
                Event::SrdoEvent(_) => {
                    let (released, _) = values(&actuator_od::NORMAL);
                    if released == 1 && !on {
                        println!("[{ms:3} ms] actuator >>> SAFE OUTPUT ON");
                        story.push(Output::On(ms));
                        on = true;
                    } else if released != 1 {
                        off(&mut on, &mut story, Output::OffEStop(ms));
                    }
                }
                Event::SrdoError(_, code) => {
                    println!("[{ms:3} ms] actuator AppSrdoError(0x1301, {code:?})");
                    off(&mut on, &mut story, Output::OffError(ms, code));
                }
                _ => {}
            }
            acknowledge(stack, &e);
        });
    }
    // on with the first pair (20 ms); off with the GFC (100 ms); on again
    // with the first pair after the E-stop (140 ms); off when SCT passes
    // after the last pair (200 ms)
    let expected = [
        Output::On(20),
        Output::OffGfc(100),
        Output::On(140),
        Output::OffError(200 + u32::from(SCT_MS) + 1, CopKernel::SrdoSctTimeout),
    ];
    println!("result: {story:?}");
    if story != expected {
        return Err(format!(
            "the output did not follow the story: expected {expected:?}"
        ));
    }
    Ok(())
}
