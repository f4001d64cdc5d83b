//! Values as device descriptions write them, and their CiA 301 encodings.
//!
//! # Numbers (CiA 306 4.6.3)
//! Decimal, hexadecimal with `0x`, octal with a leading `0`, optionally
//! negative; `$NODEID` plus a number (either order, white space allowed)
//! adds the node-ID. Tolerated with a note, because common tools write it
//! and its meaning is unambiguous: a C integer suffix (`U`, `L`, `UL`,
//! `LL`, `ULL`: CANopenNode's older editor writes `0x1234567890ABCDEFLL`).
//! A hexadecimal value of a signed type may be its two's complement bit
//! pattern (`0xFF` for INTEGER8 is −1), as python-canopen reads limits.
//!
//! # Encodings (CiA 301 7.1, little-endian)
//! | type | bytes |
//! |---|---|
//! | BOOLEAN | 1 byte, 0 or 1 |
//! | INTEGERn / UNSIGNEDn (n = 8..64 in steps of 8) | n/8 bytes, two's complement for INTEGERn |
//! | REAL32 / REAL64 | IEEE 754 binary32 / binary64 |
//! | TIME_OF_DAY / TIME_DIFFERENCE | 6 bytes: milliseconds (28 bits), 4 reserved bits (0), days (16 bits); the value is the 48-bit number |
//! | VISIBLE_STRING | the characters, one byte each |
//! | UNICODE_STRING | UTF-16 code units, 2 bytes each (`abc` is `61 00 62 00 63 00`) |
//! | OCTET_STRING / DOMAIN | the bytes, written as two hex digits each |

use cop::od::DataType;

pub use cop::od::eds::type_name;

/// A value read from the file, with what was tolerated on the way.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Encoded {
    /// CANopen byte order.
    pub data: Vec<u8>,
    /// Forms outside CiA 306 that were accepted (one sentence each).
    pub tolerated: Vec<String>,
}

/// Splits a C integer suffix (`u`, `l`, `ul`, `ll`, `ull`, `lu`, `llu`, any
/// case) off `digits`.
fn split_suffix(digits: &str) -> (&str, &str) {
    let lower = digits.to_ascii_lowercase();
    // `u` and `l` are no digits in any radix: no ambiguity.
    for s in ["ull", "llu", "ul", "lu", "ll", "u", "l"] {
        if lower.len() > s.len() && lower.ends_with(s) {
            let cut = digits.len() - s.len();
            return (&digits[..cut], &digits[cut..]);
        }
    }
    (digits, "")
}

/// One number term (no `$NODEID`), as i128.
fn parse_number(term: &str, whole: &str, tolerated: &mut Vec<String>) -> Result<i128, String> {
    let (neg, body) = match term.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, term.strip_prefix('+').unwrap_or(term)),
    };
    let (radix, digits) = if let Some(h) = body.strip_prefix("0x").or(body.strip_prefix("0X")) {
        (16, h)
    } else if body.len() > 1 && body.starts_with('0') {
        (8, &body[1..])
    } else {
        (10, body)
    };
    let (digits, suffix) = split_suffix(digits);
    if !suffix.is_empty() {
        tolerated.push(format!(
            "`{whole}`: C integer suffix `{suffix}` (not CiA 306) ignored"
        ));
    }
    if digits.is_empty() {
        return Err(format!("`{whole}` is not a number"));
    }
    if let Some(bad) = digits.chars().find(|c| !c.is_digit(radix)) {
        return Err(match radix {
            8 if bad.is_ascii_digit() => format!(
                "`{whole}`: a leading 0 makes an octal number (CiA 306) and `{bad}` is not an octal digit"
            ),
            16 => format!("`{whole}`: `{bad}` is not a hex digit"),
            _ => format!("`{whole}` is not a number"),
        });
    }
    let m = i128::from_str_radix(digits, radix)
        .map_err(|_| format!("`{whole}` is too large for any CANopen integer"))?;
    Ok(if neg { -m } else { m })
}

/// [`parse_int`] that also returns what was tolerated, and whether the
/// number was written in hex.
pub fn parse_int_noted(
    v: &str,
    node_id: Option<u8>,
    tolerated: &mut Vec<String>,
) -> Result<(i128, bool), String> {
    let compact: String = v.chars().filter(|c| !c.is_whitespace()).collect();
    if compact.is_empty() {
        return Err("no value".into());
    }
    let upper = compact.to_ascii_uppercase();
    if let Some(at) = upper.find("$NODEID") {
        let node = node_id.ok_or(
            "uses $NODEID but no node-ID is known (give --node-id or [DeviceComissioning] NodeID)",
        )?;
        let before = &compact[..at];
        let after = &compact[at + "$NODEID".len()..];
        let rest = match (before.strip_suffix('+'), after.strip_prefix('+')) {
            (Some(b), None) if after.is_empty() => b,
            (None, Some(a)) if before.is_empty() => a,
            _ if before.is_empty() && after.is_empty() => "",
            _ => {
                return Err(format!(
                    "`{v}`: CiA 306 knows `$NODEID`, `$NODEID+number` and `number+$NODEID`"
                ));
            }
        };
        let (base, hex) = if rest.is_empty() {
            (0, false)
        } else {
            if rest.contains('$') || rest.chars().skip(1).any(|c| c == '+' || c == '-') {
                return Err(format!(
                    "`{v}`: CiA 306 knows `$NODEID`, `$NODEID+number` and `number+$NODEID`"
                ));
            }
            let hex = rest.to_ascii_lowercase().starts_with("0x");
            (parse_number(rest, v.trim(), tolerated)?, hex)
        };
        return Ok((base + i128::from(node), hex));
    }
    let hex = upper.trim_start_matches('-').starts_with("0X");
    Ok((parse_number(&compact, v.trim(), tolerated)?, hex))
}

/// Parses an integer the CiA 306 way (see the module documentation).
pub fn parse_int(v: &str, node_id: Option<u8>) -> Result<i128, String> {
    parse_int_noted(v, node_id, &mut Vec::new()).map(|(n, _)| n)
}

/// The range of an integer type (BOOLEAN 0..=1, TIME types their 48 bits).
fn int_range(t: DataType) -> (i128, i128) {
    let bits = 8 * t.wire_size().unwrap_or(0) as u32;
    if t == DataType::Bool {
        (0, 1)
    } else if t.is_signed() {
        (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
    } else {
        (0, (1i128 << bits) - 1)
    }
}

/// An integer value of type `t` (hex two's complement allowed for signed
/// types), as i128.
fn int_of(
    t: DataType,
    text: &str,
    node_id: Option<u8>,
    tolerated: &mut Vec<String>,
) -> Result<i128, String> {
    let (v, hex) = parse_int_noted(text, node_id, tolerated)?;
    let (lo, hi) = int_range(t);
    let bits = 8 * t.wire_size().unwrap_or(0) as u32;
    if t.is_signed() && hex && v > hi && v < (1i128 << bits) {
        return Ok(v - (1i128 << bits));
    }
    if v < lo || v > hi {
        return Err(format!(
            "{v} is out of range {lo}..={hi} of {}",
            type_name(t)
        ));
    }
    Ok(v)
}

fn float_of(t: DataType, text: &str) -> Result<f64, String> {
    let v = text.trim();
    if v.is_empty() {
        return Ok(0.0);
    }
    let bad = || {
        format!(
            "`{v}` is not a decimal number ({} values are written like 1.5 or -2e-3)",
            type_name(t)
        )
    };
    if v.to_ascii_lowercase().contains("0x") {
        return Err(bad());
    }
    // Correctly rounded from the decimal text in the type's own width.
    if t == DataType::Real32 {
        v.parse::<f32>().map(f64::from).map_err(|_| bad())
    } else {
        v.parse::<f64>().map_err(|_| bad())
    }
}

fn hex_bytes(t: DataType, value: &str, tolerated: &mut Vec<String>) -> Result<Vec<u8>, String> {
    let v = value.trim();
    if let Some(rest) = v.strip_prefix('@') {
        return Err(format!(
            "`{v}`: CiA 306 (4.3) writes {} values as hex digits, two per byte, without prefix (`{rest}` would be {} bytes); `@` is no value form of CiA 306 (python-canopen gives the object no value)",
            type_name(t),
            rest.len() / 2
        ));
    }
    if t == DataType::Domain && v == "0" {
        tolerated.push(
            "DOMAIN value `0` (CANopenNode's editor writes it for a domain without content) read as empty".into(),
        );
        return Ok(Vec::new());
    }
    let mut digits: String = v.chars().filter(|c| !c.is_whitespace()).collect();
    if let Some(h) = digits
        .strip_prefix("0x")
        .or_else(|| digits.strip_prefix("0X"))
    {
        tolerated.push(format!(
            "`{v}`: `0x` before the hex digits of {} (not CiA 306) ignored",
            type_name(t)
        ));
        digits = h.to_string();
    }
    if let Some(bad) = digits.chars().find(|c| !c.is_ascii_hexdigit()) {
        return Err(format!(
            "`{v}`: `{bad}` is not a hex digit ({} values are two hex digits per byte, CiA 306)",
            type_name(t)
        ));
    }
    if digits.len() % 2 != 0 {
        return Err(format!(
            "`{v}`: odd number of hex digits ({} values are two hex digits per byte)",
            type_name(t)
        ));
    }
    Ok((0..digits.len())
        .step_by(2)
        .filter_map(|i| u8::from_str_radix(&digits[i..i + 2], 16).ok())
        .collect())
}

/// Encodes `value` (the text of the file) for data type `t`. An empty value
/// is 0 (numbers) or empty (strings, domains).
pub fn encode(t: DataType, value: &str, node_id: Option<u8>) -> Result<Encoded, String> {
    let value = value.trim();
    let mut tolerated = Vec::new();
    let data = match t {
        DataType::VString => {
            let odd: Vec<char> = value.chars().filter(|c| !(' '..='~').contains(c)).collect();
            if !odd.is_empty() {
                let shown: String = odd
                    .iter()
                    .map(|c| format!("{:?}", c))
                    .collect::<Vec<_>>()
                    .join(", ");
                tolerated.push(format!(
                    "VISIBLE_STRING holds the characters 0x20..0x7E (CiA 301 7.1.6.3); {shown} written as UTF-8 bytes, as CANopenNode does (UNICODE_STRING carries any character)"
                ));
            }
            value.as_bytes().to_vec()
        }
        DataType::UString => value.encode_utf16().flat_map(u16::to_le_bytes).collect(),
        DataType::OString | DataType::Domain => hex_bytes(t, value, &mut tolerated)?,
        DataType::Real32 => (float_of(t, value)? as f32).to_le_bytes().to_vec(),
        DataType::Real64 => float_of(t, value)?.to_le_bytes().to_vec(),
        DataType::Bool if matches!(value.to_ascii_lowercase().as_str(), "true" | "false") => {
            tolerated.push(format!(
                "`{value}`: CiA 306 writes BOOLEAN values as 0 or 1"
            ));
            vec![u8::from(value.eq_ignore_ascii_case("true"))]
        }
        _ => {
            let width = t.wire_size().unwrap_or(0);
            let v = if value.is_empty() {
                0
            } else {
                int_of(t, value, node_id, &mut tolerated)?
            };
            if matches!(t, DataType::TimeOfDay | DataType::TimeDiff) && v & 0xF000_0000 != 0 {
                return Err(format!(
                    "`{value}`: bits 28..31 of {} are reserved (CiA 301 7.1.6.5/6: milliseconds UNSIGNED28, 4 reserved bits, days UNSIGNED16); milliseconds end at 268435455",
                    type_name(t)
                ));
            }
            (v as u64).to_le_bytes()[..width].to_vec()
        }
    };
    Ok(Encoded { data, tolerated })
}

/// A limit or a value compared with limits.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub enum Number {
    /// Integers (signed or not).
    Int(i128),
    /// REAL32/REAL64.
    Real(f64),
}

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Number::Int(i) => write!(f, "{i}"),
            Number::Real(r) => write!(f, "{r}"),
        }
    }
}

/// True for the types LowLimit/HighLimit apply to.
pub fn has_limits(t: DataType) -> bool {
    t.is_numeric() && t != DataType::Bool
}

/// Reads a LowLimit/HighLimit of type `t`.
pub fn limit(
    t: DataType,
    text: &str,
    node_id: Option<u8>,
    tolerated: &mut Vec<String>,
) -> Result<Number, String> {
    if t.is_float() {
        float_of(t, text).map(Number::Real)
    } else {
        int_of(t, text, node_id, tolerated).map(Number::Int)
    }
}

/// The number the encoded `data` of type `t` stands for.
pub fn number(t: DataType, data: &[u8]) -> Option<Number> {
    let mut b = [0u8; 8];
    b.get_mut(..data.len())?.copy_from_slice(data);
    let raw = u64::from_le_bytes(b);
    Some(match t {
        DataType::Real32 => Number::Real(f64::from(f32::from_bits(raw as u32))),
        DataType::Real64 => Number::Real(f64::from_bits(raw)),
        t if t.is_signed() => {
            let shift = 64 - 8 * data.len() as u32;
            Number::Int(i128::from(((raw << shift) as i64) >> shift))
        }
        _ => Number::Int(i128::from(raw)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn enc(t: DataType, v: &str) -> Vec<u8> {
        encode(t, v, Some(5)).unwrap().data
    }

    #[test]
    fn integers_of_every_width() {
        // CiA 301 7.1.4/7.1.5: two's complement, little-endian.
        assert_eq!(enc(DataType::Int24, "-1"), [0xFF, 0xFF, 0xFF]);
        assert_eq!(enc(DataType::Int24, "-8388608"), [0x00, 0x00, 0x80]);
        assert_eq!(enc(DataType::UInt24, "0x123456"), [0x56, 0x34, 0x12]);
        assert_eq!(enc(DataType::Int40, "-40"), [0xD8, 0xFF, 0xFF, 0xFF, 0xFF]);
        assert_eq!(
            enc(DataType::UInt48, "0x0102030405 06"),
            [6, 5, 4, 3, 2, 1],
            "white space inside a number is ignored"
        );
        assert_eq!(
            enc(DataType::Int56, "-56"),
            [0xC8, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF]
        );
        assert_eq!(enc(DataType::Int64, "-1"), [0xFF; 8]);
        assert_eq!(enc(DataType::Int8, "0x80"), [0x80], "hex bit pattern");
        assert!(encode(DataType::Int8, "128", None).is_err());
        assert!(encode(DataType::UInt40, "0x10000000000", None).is_err());
        assert!(encode(DataType::Bool, "2", None).is_err());
    }

    #[test]
    fn c_suffix_is_tolerated_with_a_note() {
        let e = encode(DataType::Int64, "0x1234567890ABCDEFLL", None).unwrap();
        assert_eq!(e.data, 0x1234_5678_90AB_CDEFu64.to_le_bytes());
        assert_eq!(e.tolerated.len(), 1);
        assert!(e.tolerated[0].contains("suffix `LL`"), "{:?}", e.tolerated);
        assert_eq!(enc(DataType::UInt32, "500UL"), 500u32.to_le_bytes());
        let e = encode(DataType::UInt8, "08", None).unwrap_err();
        assert!(e.contains("octal"), "{e}");
    }

    #[test]
    fn node_id_forms() {
        assert_eq!(parse_int("$NODEID+0x180", Some(3)), Ok(0x183));
        assert_eq!(parse_int("0x200 + $NODEID", Some(3)), Ok(0x203));
        assert_eq!(parse_int("$nodeid", Some(3)), Ok(3));
        assert_eq!(parse_int("$NODEID+0x80000180LL", Some(3)), Ok(0x8000_0183));
        assert!(parse_int("$NODEID-1", Some(3)).is_err());
        assert!(parse_int("1+2", Some(3)).is_err());
        assert!(parse_int("$NODEID+1+2", Some(3)).is_err());
    }

    #[test]
    fn reals_and_times() {
        assert_eq!(enc(DataType::Real32, "1.5"), 1.5f32.to_le_bytes());
        assert_eq!(enc(DataType::Real64, "-2e-3"), (-2e-3f64).to_le_bytes());
        assert!(encode(DataType::Real32, "0x3FC00000", None).is_err());
        // TIME_OF_DAY: 12:00:00.000 on day 1 = 43,200,000 ms, day 1.
        let v = 43_200_000u64 | (1 << 32);
        assert_eq!(
            enc(DataType::TimeOfDay, &v.to_string()),
            v.to_le_bytes()[..6]
        );
        let e = encode(DataType::TimeDiff, "0x10000000", None).unwrap_err();
        assert!(e.contains("reserved"), "{e}");
    }

    #[test]
    fn strings_and_bytes() {
        // CiA 301 7.1.6.4: UNICODE_STRING is 16-bit characters.
        assert_eq!(enc(DataType::UString, "abc"), [0x61, 0, 0x62, 0, 0x63, 0]);
        assert_eq!(enc(DataType::UString, "\u{2713}"), [0x13, 0x27]);
        assert_eq!(
            enc(DataType::UString, "\u{1F600}"),
            [0x3D, 0xD8, 0x00, 0xDE]
        );
        assert_eq!(enc(DataType::OString, "AB cd"), [0xAB, 0xCD]);
        let e = encode(DataType::Domain, "@ABCD", None).unwrap_err();
        assert!(e.contains("`@` is no value form"), "{e}");
        let e = encode(DataType::OString, "ABC", None).unwrap_err();
        assert!(e.contains("odd number"), "{e}");
        let e = encode(DataType::VString, "1 \u{20AC}", None).unwrap();
        assert_eq!(e.data, "1 \u{20AC}".as_bytes());
        assert_eq!(e.tolerated.len(), 1);
        assert!(
            encode(DataType::VString, "plain", None)
                .unwrap()
                .tolerated
                .is_empty()
        );
    }

    #[test]
    fn numbers_for_limits() {
        assert_eq!(
            number(DataType::Int24, &[0xFF, 0xFF, 0xFF]),
            Some(Number::Int(-1))
        );
        assert_eq!(
            number(DataType::UInt16, &[0x34, 0x12]),
            Some(Number::Int(0x1234))
        );
        assert_eq!(
            limit(DataType::Int32, "0x80000000", None, &mut Vec::new()),
            Ok(Number::Int(-0x8000_0000))
        );
        assert!(Number::Real(4.5) < Number::Real(5.2));
    }
}
