//! Captures of the simulated bus for the tools people already use: a pcap
//! file of SocketCAN frames (Wireshark, tshark) and a `candump -l` log
//! (can-utils' `canplayer`, `log2asc`, ...).
//!
//! Timestamps are the simulated clock, not the wall clock: the first frame
//! of a bus at tick 0 is at [`EPOCH_S`] seconds (2023-11-14 22:13:20 UTC),
//! and every 100 µs tick of the bus is 100 µs in the capture. The clock of
//! a capture only moves forward: a tick counter that wraps (or is set back
//! by [`super::SimBus::set_time`]) continues from where it was, modulo 2^32
//! ticks.
//!
//! A frame is written once per copy that reaches the bus: a frame a fault
//! filter drops is not in the capture, a duplicated one is there twice.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use crate::port::{CanFrame, Ticks};

/// Seconds of the capture clock at bus tick 0 (the Unix time
/// 1 700 000 000).
pub const EPOCH_S: u64 = 1_700_000_000;

/// The environment variable that names the pcap file every new
/// [`super::SimBus`] writes.
pub const ENV_PCAP: &str = "COP_SIM_PCAP";
/// The environment variable that names the `candump -l` log every new
/// [`super::SimBus`] writes.
pub const ENV_CANDUMP: &str = "COP_SIM_CANDUMP";

/// pcap link type 227, `LINKTYPE_CAN_SOCKETCAN` (tcpdump.org link-layer
/// header types).
pub const LINKTYPE_CAN_SOCKETCAN: u32 = 227;
/// Bytes of one SocketCAN record: `struct can_frame` (Linux
/// `include/uapi/linux/can.h`): 4 bytes identifier and flags, 1 byte
/// length, 3 bytes padding / reserved, 8 data bytes.
pub const SOCKETCAN_RECORD: usize = 16;

/// Flag of an extended (29-bit) identifier in the SocketCAN identifier
/// word (`CAN_EFF_FLAG`).
pub const CAN_EFF_FLAG: u32 = 0x8000_0000;
/// Flag of a remote frame in the SocketCAN identifier word
/// (`CAN_RTR_FLAG`).
pub const CAN_RTR_FLAG: u32 = 0x4000_0000;

/// The 24-byte pcap file header: magic 0xA1B2C3D4 (microsecond
/// timestamps), version 2.4, zone 0, accuracy 0, snapshot length, link
/// type; every field in the writer's byte order, which is little-endian
/// here (the magic tells a reader which).
pub fn pcap_file_header() -> [u8; 24] {
    let mut h = [0u8; 24];
    let fields: [(usize, &[u8]); 6] = [
        (0, &0xA1B2_C3D4u32.to_le_bytes()),
        (4, &2u16.to_le_bytes()),
        (6, &4u16.to_le_bytes()),
        (8, &[0u8; 8]),
        (16, &(SOCKETCAN_RECORD as u32).to_le_bytes()),
        (20, &LINKTYPE_CAN_SOCKETCAN.to_le_bytes()),
    ];
    for (at, bytes) in fields {
        for (d, s) in h.iter_mut().skip(at).zip(bytes) {
            *d = *s;
        }
    }
    h
}

/// The SocketCAN record of a frame: identifier word big-endian (network
/// byte order, as Wireshark reads link type 227) with `CAN_EFF_FLAG` for a
/// 29-bit identifier and `CAN_RTR_FLAG` for a remote frame, the length
/// byte, three zero bytes, the eight data bytes (zero beyond the length,
/// and all zero for a remote frame).
pub fn socketcan_record(f: &CanFrame) -> [u8; SOCKETCAN_RECORD] {
    let mut word = f.id.id();
    if f.id.is_extended() {
        word |= CAN_EFF_FLAG;
    }
    if f.rtr {
        word |= CAN_RTR_FLAG;
    }
    let mut r = [0u8; SOCKETCAN_RECORD];
    for (d, s) in r.iter_mut().zip(word.to_be_bytes()) {
        *d = s;
    }
    if let Some(len) = r.get_mut(4) {
        *len = f.len.min(8);
    }
    if !f.rtr {
        for (d, s) in r.iter_mut().skip(8).zip(f.payload()) {
            *d = *s;
        }
    }
    r
}

/// The pcap record header (16 bytes, little-endian like the file header):
/// seconds, microseconds, captured length, original length.
pub fn pcap_record_header(micros: u64) -> [u8; 16] {
    let secs = (micros / 1_000_000) as u32;
    let usecs = (micros % 1_000_000) as u32;
    let len = SOCKETCAN_RECORD as u32;
    let mut h = [0u8; 16];
    let words = [secs, usecs, len, len];
    for (chunk, w) in h.chunks_mut(4).zip(words) {
        chunk.copy_from_slice(&w.to_le_bytes());
    }
    h
}

/// One line of a `candump -l` log (without the newline):
/// `(1700000000.000100) can0 101#01020304`. 29-bit identifiers have eight
/// hex digits, 11-bit ones three; a remote frame is `#R` followed by its
/// length; a frame without data is `#` alone.
pub fn candump_log_line(micros: u64, iface: &str, f: &CanFrame) -> String {
    let id = if f.id.is_extended() {
        format!("{:08X}", f.id.id())
    } else {
        format!("{:03X}", f.id.id())
    };
    let data = if f.rtr {
        format!("R{}", f.len.min(8))
    } else {
        f.payload().iter().map(|b| format!("{b:02X}")).collect()
    };
    format!(
        "({}.{:06}) {iface} {id}#{data}",
        micros / 1_000_000,
        micros % 1_000_000
    )
}

/// The writers of one bus: a pcap file and/or a candump log, and the
/// forward-only clock of the capture.
pub(crate) struct Capture {
    pcap: Option<BufWriter<File>>,
    candump: Option<BufWriter<File>>,
    last: Option<Ticks>,
    elapsed_ticks: u64,
}

impl Capture {
    /// Creates (truncates) the files named; `None` leaves that format out.
    pub(crate) fn create(pcap: Option<&Path>, candump: Option<&Path>) -> io::Result<Capture> {
        let pcap = match pcap {
            Some(p) => {
                let mut w = BufWriter::new(File::create(p)?);
                w.write_all(&pcap_file_header())?;
                Some(w)
            }
            None => None,
        };
        let candump = match candump {
            Some(p) => Some(BufWriter::new(File::create(p)?)),
            None => None,
        };
        Ok(Capture {
            pcap,
            candump,
            last: None,
            elapsed_ticks: 0,
        })
    }

    /// The capture files the environment names ([`ENV_PCAP`],
    /// [`ENV_CANDUMP`]); `None` when it names none.
    pub(crate) fn from_env() -> Option<io::Result<Capture>> {
        let pcap = std::env::var_os(ENV_PCAP).filter(|v| !v.is_empty());
        let candump = std::env::var_os(ENV_CANDUMP).filter(|v| !v.is_empty());
        if pcap.is_none() && candump.is_none() {
            return None;
        }
        Some(Capture::create(
            pcap.as_deref().map(Path::new),
            candump.as_deref().map(Path::new),
        ))
    }

    /// Microseconds since the Unix epoch of the capture clock at `now`.
    fn micros(&mut self, now: Ticks) -> u64 {
        if let Some(last) = self.last {
            self.elapsed_ticks += u64::from(now.since(last));
        } else {
            self.elapsed_ticks = u64::from(now.0);
        }
        self.last = Some(now);
        EPOCH_S * 1_000_000 + self.elapsed_ticks * 100
    }

    /// Writes one frame that was on the bus at `now` and `sub_us`
    /// microseconds (a physical bus: its end of frame within the tick,
    /// 0..=99; the ideal bus: 0).
    pub(crate) fn record(&mut self, now: Ticks, sub_us: u64, f: &CanFrame) -> io::Result<()> {
        let micros = self.micros(now) + sub_us;
        if let Some(w) = self.pcap.as_mut() {
            w.write_all(&pcap_record_header(micros))?;
            w.write_all(&socketcan_record(f))?;
        }
        if let Some(w) = self.candump.as_mut() {
            writeln!(w, "{}", candump_log_line(micros, "can0", f))?;
        }
        Ok(())
    }

    /// Writes out what is buffered.
    pub(crate) fn flush(&mut self) -> io::Result<()> {
        if let Some(w) = self.pcap.as_mut() {
            w.flush()?;
        }
        if let Some(w) = self.candump.as_mut() {
            w.flush()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::port::CanId;

    #[test]
    fn file_header_is_the_documented_pcap_layout() {
        // pcap file format (tcpdump.org, draft-ietf-opsawg-pcap): magic
        // A1B2C3D4, major 2, minor 4, thiszone 0, sigfigs 0, snaplen,
        // LinkType 227 (LINKTYPE_CAN_SOCKETCAN); little-endian writer.
        assert_eq!(
            pcap_file_header(),
            [
                0xD4, 0xC3, 0xB2, 0xA1, 2, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 0, 0, 227, 0, 0,
                0
            ]
        );
    }

    #[test]
    fn socketcan_record_standard_extended_remote() {
        // struct can_frame (linux/can.h): can_id in network byte order for
        // LINKTYPE_CAN_SOCKETCAN, CAN_EFF_FLAG 0x80000000, CAN_RTR_FLAG
        // 0x40000000, then can_dlc, 3 bytes pad/res, data[8].
        let f = CanFrame::new(CanId::std_masked(0x101), &[0x01, 0x02, 0xFE, 0xFD]);
        assert_eq!(
            socketcan_record(&f),
            [0, 0, 1, 1, 4, 0, 0, 0, 0x01, 0x02, 0xFE, 0xFD, 0, 0, 0, 0]
        );
        let e = CanFrame::new(CanId::ext(0x1234_5678).unwrap(), &[0xAA]);
        assert_eq!(
            socketcan_record(&e),
            [
                0x92, 0x34, 0x56, 0x78, 1, 0, 0, 0, 0xAA, 0, 0, 0, 0, 0, 0, 0
            ]
        );
        let r = CanFrame::remote(CanId::std_masked(0x702), 1);
        assert_eq!(
            socketcan_record(&r),
            [0x40, 0, 0x07, 0x02, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
        );
    }

    #[test]
    fn record_header_splits_seconds_and_microseconds() {
        let h = pcap_record_header(1_700_000_000_000_100);
        assert_eq!(&h[0..4], &1_700_000_000u32.to_le_bytes());
        assert_eq!(&h[4..8], &100u32.to_le_bytes());
        assert_eq!(&h[8..16], &[16, 0, 0, 0, 16, 0, 0, 0]);
    }

    #[test]
    fn candump_log_lines_as_canplayer_reads_them() {
        // can-utils lib.c: "<id>#<data>" with 3 or 8 hex digits, "R[len]"
        // for a remote frame; candump -l prefixes "(sec.usec) iface ".
        let t = 1_700_000_000_000_000 + 2_500;
        let f = CanFrame::new(CanId::std_masked(0x123), &[0xDE, 0xAD, 0xBE, 0xEF]);
        assert_eq!(
            candump_log_line(t, "can0", &f),
            "(1700000000.002500) can0 123#DEADBEEF"
        );
        let g = CanFrame::new(CanId::std_masked(0x001), &[]);
        assert_eq!(
            candump_log_line(t, "can0", &g),
            "(1700000000.002500) can0 001#"
        );
        let e = CanFrame::new(CanId::ext(0x0000_0ABC).unwrap(), &[1]);
        assert_eq!(
            candump_log_line(t, "can0", &e),
            "(1700000000.002500) can0 00000ABC#01"
        );
        let r = CanFrame::remote(CanId::std_masked(0x702), 1);
        assert_eq!(
            candump_log_line(t, "can0", &r),
            "(1700000000.002500) can0 702#R1"
        );
    }

    #[test]
    #[cfg_attr(
        miri,
        ignore = "writes a file; Miri runs isolated from the file system"
    )]
    fn capture_clock_runs_on_across_a_tick_wrap() {
        let dir = std::env::temp_dir().join(format!("cop_capture_wrap_{}", std::process::id()));
        let mut c = Capture::create(None, Some(&dir)).unwrap();
        assert_eq!(
            c.micros(Ticks(u32::MAX - 1)),
            (EPOCH_S * 1_000_000) + (u64::from(u32::MAX) - 1) * 100
        );
        assert_eq!(
            c.micros(Ticks(3)),
            (EPOCH_S * 1_000_000) + (u64::from(u32::MAX) + 4) * 100
        );
        drop(c);
        let _ = std::fs::remove_file(dir);
    }
}
