//! TIME object (CiA 301 7.2.6): one data frame of six bytes carrying a
//! TIME_OF_DAY value (CiA 301 7.1.6.5): milliseconds after midnight in
//! the low 28 bits of a little-endian UNSIGNED32 (bits 28–31 reserved, 0),
//! then the days since 1 January 1984 as a little-endian UNSIGNED16.

use crate::port::{CanFrame, CanId};

/// Default COB-ID of the TIME object (object 0x1012, CiA 301 7.5.2.14).
pub const TIME_DEFAULT_COB_ID: u32 = 0x100;

/// Milliseconds in one day: a time of day is below this value.
pub const MS_PER_DAY: u32 = 86_400_000;

/// Data length of a TIME frame.
pub const TIME_DLC: u8 = 6;

/// A TIME_OF_DAY value (`tTimeOfDay`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TimeOfDay {
    /// Milliseconds after midnight (`m_dwMs`), below [`MS_PER_DAY`].
    pub ms: u32,
    /// Days since 1 January 1984 (`m_wDays`).
    pub days: u16,
}

impl TimeOfDay {
    /// `Some` when `ms` is a time of day (below [`MS_PER_DAY`]), so that
    /// only values the frame can carry exist past this point.
    pub const fn new(ms: u32, days: u16) -> Option<TimeOfDay> {
        if ms < MS_PER_DAY {
            Some(TimeOfDay { ms, days })
        } else {
            None
        }
    }
}

/// Encodes a TIME frame. The reserved bits 28–31 of the millisecond field
/// are sent as 0.
pub fn encode(id: CanId, t: &TimeOfDay) -> CanFrame {
    let ms = (t.ms & 0x0FFF_FFFF).to_le_bytes();
    let d = t.days.to_le_bytes();
    CanFrame::new(id, &[ms[0], ms[1], ms[2], ms[3], d[0], d[1]])
}

/// Decodes a TIME frame (consumer side): a data frame of DLC 6 whose
/// millisecond field is a time of day; the reserved bits are ignored.
pub fn decode(frame: &CanFrame) -> Option<TimeOfDay> {
    if frame.rtr || frame.len != TIME_DLC {
        return None;
    }
    let d = frame.data;
    let ms = u32::from_le_bytes([d[0], d[1], d[2], d[3]]) & 0x0FFF_FFFF;
    TimeOfDay::new(ms, u16::from_le_bytes([d[4], d[5]]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_bytes_ms_then_days_little_endian() {
        // 12:00:00.000 on 1 January 2024: 43 200 000 ms = 0x0293_2E00,
        // 14 610 days after 1 January 1984 = 0x3912 (CiA 301 7.1.6.5).
        let t = TimeOfDay::new(43_200_000, 14_610).unwrap();
        let f = encode(CanId::std_masked(0x100), &t);
        assert_eq!(f.payload(), &[0x00, 0x2E, 0x93, 0x02, 0x12, 0x39]);
        assert_eq!(decode(&f), Some(t));
    }

    #[test]
    fn only_times_of_day_exist() {
        assert!(TimeOfDay::new(MS_PER_DAY - 1, 0).is_some());
        assert!(TimeOfDay::new(MS_PER_DAY, 0).is_none());
        // Reserved bits on the wire are not part of the value.
        let f = CanFrame::new(CanId::std_masked(0x100), &[1, 0, 0, 0xF0, 2, 0]);
        assert_eq!(decode(&f), TimeOfDay::new(1, 2));
        let short = CanFrame::new(CanId::std_masked(0x100), &[1, 0, 0, 0, 2]);
        assert_eq!(decode(&short), None);
    }
}
