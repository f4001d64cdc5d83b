use std::cell::Cell;
use std::collections::VecDeque;

use embedded_can::{ErrorKind, ExtendedId, Frame, Id, StandardId};

use super::*;

/// The frame type of the scripted driver.
type HalFrame = PlainFrame;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct HalError(ErrorKind);

impl embedded_can::Error for HalError {
    fn kind(&self) -> ErrorKind {
        self.0
    }
}

/// A driver with a script of answers.
#[derive(Default)]
struct Hal {
    sent: Vec<HalFrame>,
    tx_answers: VecDeque<nb::Result<Option<HalFrame>, HalError>>,
    rx: VecDeque<nb::Result<HalFrame, HalError>>,
}

impl embedded_can::nb::Can for Hal {
    type Frame = HalFrame;
    type Error = HalError;
    fn transmit(&mut self, frame: &HalFrame) -> nb::Result<Option<HalFrame>, HalError> {
        let answer = self.tx_answers.pop_front().unwrap_or(Ok(None));
        if answer.is_ok() {
            self.sent.push(frame.clone());
        }
        answer
    }
    fn receive(&mut self) -> nb::Result<HalFrame, HalError> {
        self.rx.pop_front().unwrap_or(Err(nb::Error::WouldBlock))
    }
}

impl embedded_can::blocking::Can for Hal {
    type Frame = HalFrame;
    type Error = HalError;
    fn transmit(&mut self, frame: &HalFrame) -> Result<(), HalError> {
        match self.tx_answers.pop_front() {
            Some(Err(nb::Error::Other(e))) => Err(e),
            _ => {
                self.sent.push(frame.clone());
                Ok(())
            }
        }
    }
    fn receive(&mut self) -> Result<HalFrame, HalError> {
        match self.rx.pop_front() {
            Some(Ok(f)) => Ok(f),
            Some(Err(nb::Error::Other(e))) => Err(e),
            _ => Err(HalError(ErrorKind::Other)),
        }
    }
}

fn std_id(id: u16) -> Id {
    Id::Standard(StandardId::new(id).unwrap())
}

fn ext_id(id: u32) -> Id {
    Id::Extended(ExtendedId::new(id).unwrap())
}

#[test]
fn identifiers_both_ways() {
    // 11-bit: 0x000..=0x7FF; 29-bit: 0..=0x1FFF_FFFF (ISO 11898-1)
    for raw in [0x000u16, 0x001, 0x101, 0x180, 0x7FF] {
        let id = id_from_embedded(std_id(raw));
        assert_eq!((id.id(), id.is_extended()), (u32::from(raw), false));
        assert_eq!(id_to_embedded(id), Some(std_id(raw)));
    }
    for raw in [0u32, 0x101, 0x800, 0x1234_5678, 0x1FFF_FFFF] {
        let id = id_from_embedded(ext_id(raw));
        assert_eq!((id.id(), id.is_extended()), (raw, true));
        assert_eq!(id_to_embedded(id), Some(ext_id(raw)));
    }
}

#[test]
fn frames_both_ways() {
    let data = HalFrame::new(std_id(0x101), &[1, 2, 0xFE, 0xFD]).unwrap();
    let f = frame_from_embedded(&data).unwrap();
    assert_eq!(
        f,
        CanFrame::new(CanId::std_masked(0x101), &[1, 2, 0xFE, 0xFD])
    );
    assert_eq!(frame_to_embedded::<HalFrame>(&f), Some(data));

    let ext = HalFrame::new(ext_id(0x18FF_1234), &[0xAA; 8]).unwrap();
    let f = frame_from_embedded(&ext).unwrap();
    assert_eq!(
        f,
        CanFrame::new(CanId::ext(0x18FF_1234).unwrap(), &[0xAA; 8])
    );
    assert_eq!(frame_to_embedded::<HalFrame>(&f), Some(ext));

    // a remote frame keeps its DLC and has no data (CiA 301 node guarding
    // asks with a remote frame of DLC 1 on 0x700 + node-ID)
    let rtr = HalFrame::new_remote(std_id(0x702), 1).unwrap();
    let f = frame_from_embedded(&rtr).unwrap();
    assert_eq!(f, CanFrame::remote(CanId::std_masked(0x702), 1));
    assert_eq!(frame_to_embedded::<HalFrame>(&f), Some(rtr));
    let rtr_ext = HalFrame::new_remote(ext_id(0x0ABC_DEF0), 0).unwrap();
    let f = frame_from_embedded(&rtr_ext).unwrap();
    assert!(f.rtr && f.id.is_extended() && f.len == 0);
    assert_eq!(frame_to_embedded::<HalFrame>(&f), Some(rtr_ext));

    // GFC: 0x001 with DLC 0 (CiA 304)
    let gfc = HalFrame::new(std_id(0x001), &[]).unwrap();
    assert_eq!(frame_from_embedded(&gfc).map(|f| f.len), Some(0));
}

#[test]
fn tick_function_clocks() {
    let t = Cell::new(7u32);
    let ticks = TickFn::ticks(|| t.get());
    let ms = TickFn::millis(|| t.get());
    assert_eq!(ticks.now(), Ticks(7));
    assert_eq!(ms.now(), Ticks(70));
    t.set(u32::MAX);
    // a millisecond counter at its end wraps the tick counter
    assert_eq!(ms.now(), Ticks(u32::MAX.wrapping_mul(10)));
}

#[test]
fn nb_port_sends_receives_and_maps_errors() {
    let now = Cell::new(100u32);
    let mut hal = Hal::default();
    hal.rx
        .push_back(Ok(HalFrame::new(std_id(0x102), &[0xFE]).unwrap()));
    hal.rx
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Overrun))));
    hal.rx
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Crc))));
    hal.tx_answers.push_back(Err(nb::Error::WouldBlock));
    hal.tx_answers.push_back(Err(nb::Error::WouldBlock));
    hal.tx_answers
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Acknowledge))));
    hal.tx_answers
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Other))));
    let mut port = NbPort::new(hal, TickFn::ticks(|| now.get()));

    let f = CanFrame::new(CanId::std_masked(0x101), &[1]);
    assert_eq!(
        port.send(&f, Priority::High),
        Err(CopKernel::CdrvTxBuffHighOverrun)
    );
    assert_eq!(
        port.send(&f, Priority::Low),
        Err(CopKernel::CdrvTxBuffLowOverrun)
    );
    assert_eq!(port.send(&f, Priority::High), Err(CopKernel::CdrvBusy));
    assert_eq!(
        port.send(&f, Priority::High),
        Err(CopKernel::CdrvHostOsError)
    );
    assert_eq!(port.send(&f, Priority::High), Ok(()));
    assert_eq!(port.driver_mut().sent.len(), 1);

    let rx = port.receive().unwrap();
    assert_eq!(
        rx,
        RxFrame {
            frame: CanFrame::new(CanId::std_masked(0x102), &[0xFE]),
            time: Ticks(100)
        }
    );
    assert_eq!(port.receive(), None);
    assert!(port.status().rx_overrun);
    assert!(!port.status().rx_overrun);
    assert_eq!(port.receive(), None);
    assert_eq!(port.rx_errors(), 1);
    assert!(!port.take_rx_overrun());
}

#[test]
fn nb_port_sends_a_displaced_frame_again_first() {
    let mut hal = Hal::default();
    let low = HalFrame::new(std_id(0x181), &[9]).unwrap();
    hal.tx_answers.push_back(Ok(Some(low.clone())));
    hal.tx_answers.push_back(Err(nb::Error::WouldBlock));
    let mut port = NbPort::new(hal, TickFn::ticks(|| 0));
    let srdo = CanFrame::new(CanId::std_masked(0x101), &[1]);
    assert_eq!(port.send(&srdo, Priority::High), Ok(()));
    // the retry finds the mailbox full: the new frame waits too
    assert_eq!(
        port.send(&srdo, Priority::Low),
        Err(CopKernel::CdrvTxBuffHighOverrun)
    );
    assert_eq!(port.receive(), None); // retried here, sent
    assert_eq!(port.send(&srdo, Priority::High), Ok(()));
    let sent: Vec<u32> = port
        .into_inner()
        .sent
        .iter()
        .map(|f| match f.id {
            Id::Standard(s) => u32::from(s.as_raw()),
            Id::Extended(e) => e.as_raw(),
        })
        .collect();
    assert_eq!(sent, [0x101, 0x181, 0x101]);
}

#[test]
fn blocking_port_queue_overrun_and_errors() {
    let now = Cell::new(5u32);
    let mut hal = Hal::default();
    for i in 0..3u8 {
        hal.rx
            .push_back(Ok(HalFrame::new(std_id(0x181), &[i]).unwrap()));
    }
    hal.rx
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Overrun))));
    hal.rx
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Form))));
    hal.tx_answers
        .push_back(Err(nb::Error::Other(HalError(ErrorKind::Overrun))));
    let mut port: BlockingPort<_, _, 2> = BlockingPort::new(hal, TickFn::millis(|| now.get()));
    assert_eq!(port.receive_blocking(), Ok(true));
    now.set(6);
    assert_eq!(port.receive_blocking(), Ok(true));
    assert_eq!(port.receive_blocking(), Ok(false)); // queue of 2 full
    assert!(port.status().rx_overrun);
    assert_eq!(port.receive_blocking(), Ok(false)); // the driver's overrun
    assert!(port.take_rx_overrun());
    assert_eq!(port.receive_blocking(), Err(CopKernel::CdrvHostOsError));
    let a = port.receive().unwrap();
    let b = port.receive().unwrap();
    assert_eq!((a.frame.data[0], a.time), (0, Ticks(50)));
    assert_eq!((b.frame.data[0], b.time), (1, Ticks(60)));
    assert_eq!(port.receive(), None);
    let f = CanFrame::new(CanId::std_masked(0x101), &[1]);
    assert_eq!(
        port.send(&f, Priority::High),
        Err(CopKernel::CdrvTxBuffHighOverrun)
    );
    assert_eq!(port.send(&f, Priority::High), Ok(()));
    assert_eq!(port.driver_mut().sent.len(), 1);
}
