//! What the dcf2bin tests share: a node's static dictionary (the firmware
//! part the dynamic OD is added to), a node on the simulated bus, the
//! python-canopen dump of a file, temporary folders.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use cop::ccm::Stack;
use cop::od::ObjectDictionary;
use cop::sim::{SimBus, SimPort};

/// A node's static dictionary, the one the sample DCF was written for:
/// 0x1000, 0x1001, 0x1017, 0x1018, RPDO 1 and TPDO 1 (invalid, empty
/// mapping). Each expansion has its own variables and pool.
#[macro_export]
macro_rules! node {
    ($name:ident) => {
        #[allow(dead_code)]
        mod $name {
            use cop::od::dynamic::DynPool;
            use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
            use cop::pdo::PDO_MAX_MAPPENTRIES;
            use cop::pdo::decl::{
                CommuDefaults, CommuVars, MappDefaults, MappVars, commu_subs, mapp_subs,
            };
            use core::sync::atomic::AtomicU8;

            pub static POOL: DynPool<4096> = DynPool::new();
            static DEVICE: [u8; 4] = 0x0001_0191u32.to_ne_bytes();
            static S1000: [ObdSubEntry; 1] =
                [ObdSubEntry::rom(0, DataType::UInt32, Access::R, &DEVICE)];
            static ERR: [AtomicU8; 1] = decl::zeroed();
            static S1001: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt8,
                Access::R,
                &ERR,
                Some(&[0]),
            )];
            static HB: [AtomicU8; 2] = decl::zeroed();
            static S1017: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt16,
                Access::SRW,
                &HB,
                Some(&[0, 0]),
            )];
            static VENDOR: [u8; 4] = 0x0000_0123u32.to_ne_bytes();
            static S1018: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                ObdSubEntry::rom(1, DataType::UInt32, Access::R, &VENDOR),
            ];
            static V1400: CommuVars = CommuVars::new();
            static D1400: CommuDefaults = CommuDefaults::new(0x8000_0200, 255, 0, 0);
            static S1400: [ObdSubEntry; 5] = commu_subs(&V1400, &D1400);
            static V1600: MappVars = MappVars::new();
            static D1600: MappDefaults = MappDefaults::new(&[]);
            static S1600: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1600, &D1600);
            static V1800: CommuVars = CommuVars::new();
            static D1800: CommuDefaults = CommuDefaults::new(0x8000_0180, 255, 0, 0);
            static S1800: [ObdSubEntry; 5] = commu_subs(&V1800, &D1800);
            static V1A00: MappVars = MappVars::new();
            static D1A00: MappDefaults = MappDefaults::new(&[]);
            static S1A00: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1A00, &D1A00);
            static GENERIC: [ObdEntry; 8] = [
                ObdEntry::new(0x1000, &S1000, None),
                ObdEntry::new(0x1001, &S1001, None),
                ObdEntry::new(0x1017, &S1017, None),
                ObdEntry::new(0x1018, &S1018, None),
                ObdEntry::new(0x1400, &S1400, None),
                ObdEntry::new(0x1600, &S1600, None),
                ObdEntry::new(0x1800, &S1800, None),
                ObdEntry::new(0x1A00, &S1A00, None),
            ];

            pub fn od() -> ObjectDictionary {
                ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
            }
        }
    };
}

/// A node on the bus, connected (PRE-OPERATIONAL).
pub fn node(bus: &SimBus, od: ObjectDictionary, id: u8) -> (Stack, SimPort) {
    let mut port = bus.attach(64);
    let mut stack = Stack::new(od, id).unwrap();
    while stack.drain(&mut port, bus.now()).is_some() {}
    stack.connect().unwrap();
    while stack.drain(&mut port, bus.now()).is_some() {}
    (stack, port)
}

/// The sample DCF of the tests.
pub fn sample() -> PathBuf {
    data("sample.dcf")
}

/// A file of tests/data.
pub fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// One subindex as python-canopen read it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PyVar {
    pub index: u16,
    pub sub: u8,
    pub data_type: u16,
    pub access: String,
    pub pdo: bool,
    /// `None` when python-canopen has no value; `ERR` when it cannot
    /// encode the value it read.
    pub hex: Option<String>,
}

/// Runs tests/py/od_dump.py on `file`.
pub fn python_dump(file: &Path) -> Vec<PyVar> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/py/od_dump.py");
    let out = Command::new("python3")
        .arg(&script)
        .arg(file)
        .output()
        .expect("python3 runs (scripts/setup.sh installs it with python-canopen)");
    assert!(
        out.status.success(),
        "python-canopen could not load {}:\n{}",
        file.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            let f: Vec<&str> = l.split(' ').collect();
            PyVar {
                index: u16::from_str_radix(f[0], 16).unwrap(),
                sub: u8::from_str_radix(f[1], 16).unwrap(),
                data_type: u16::from_str_radix(f[2], 16).unwrap(),
                access: f[3].to_string(),
                pdo: f[4] == "1",
                hex: match f[5] {
                    "NONE" => None,
                    "-" => Some(String::new()),
                    s => Some(s.to_string()),
                },
            }
        })
        .collect()
}

/// A fresh temporary folder for one test.
pub fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("dcf2bin-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Hex digits of bytes, upper case.
pub fn hex(b: &[u8]) -> String {
    b.iter().map(|x| format!("{x:02X}")).collect()
}

/// Runs the dcf2bin command line.
pub fn dcf2bin(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dcf2bin"))
        .args(args)
        .output()
        .unwrap()
}

/// Output bytes as text.
pub fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}
