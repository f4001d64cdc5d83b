"""tshark with tools/wireshark/cop_srdo.lua over the captures the project makes.

Run by the `wireshark` stage of scripts/test.sh, which first writes the
captures:

    COP_CAPTURES=DIR            cargo run --example fault_captures -- DIR
                                (one pcap per fault class, manifest.txt,
                                consumer.dcf)
    COP_SAFETY_DEMO=PROGRAM     the C safety demo (examples_c/safety_demo),
                                run here with COP_SIM_PCAP / COP_SIM_CANDUMP
    COP_RUST_CAPTURES=DIR       the pcap files of the Rust examples
                                (safety_sensor, safety_actuator) written
                                with COP_SIM_PCAP

    python3 -m unittest discover -s tools/wireshark -p 'test_*.py'

Each capture is dissected with `tshark -2 -T pdml`; the expert infos of each
frame (their field names, e.g. cop_srdo.order) are compared with what the
capture must show, and nothing else may be reported with error severity.
"""

import os
import re
import struct
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
DISSECTOR = os.path.join(HERE, "cop_srdo.lua")

# Wireshark's expert severities (epan/proto.h: PI_ERROR 0x00800000).
PI_ERROR = 0x00800000


def dissect(pcap, *prefs):
    """Per frame: (expert fields of cop_srdo, error severities, status, ok, kind)."""
    cmd = ["tshark", "-2", "-n", "-X", "lua_script:" + DISSECTOR, "-r", pcap, "-T", "pdml"]
    for p in prefs:
        cmd += ["-o", p]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    frames = {}
    for packet in ET.fromstring(out).iter("packet"):
        number = None
        experts = []
        errors = 0
        fields = {}
        for field in packet.iter("field"):
            name = field.get("name")
            if name == "frame.number":
                number = int(field.get("show"))
            elif name == "_ws.expert":
                for sub in field:
                    if sub.get("name", "").startswith("cop_srdo."):
                        experts.append(sub.get("name"))
                    if sub.get("name") == "_ws.expert.severity" and int(sub.get("show")) == PI_ERROR:
                        errors += 1
            elif name in ("cop_srdo.status", "cop_srdo.ok", "cop_srdo.kind", "cop_srdo.number"):
                fields[name] = field.get("show")
        frames[number] = (experts, errors, fields)
    return frames


def error_reports(frames):
    return sorted((n, e) for n, (experts, _, _) in frames.items() for e in experts)


class FaultCaptures(unittest.TestCase):
    """One capture per fault class of the campaign (src/sim/faults.rs)."""

    @classmethod
    def setUpClass(cls):
        cls.dir = os.environ.get("COP_CAPTURES")
        if not cls.dir:
            raise unittest.SkipTest("COP_CAPTURES not set (scripts/test.sh wireshark sets it)")
        cls.manifest = []
        with open(os.path.join(cls.dir, "manifest.txt")) as f:
            for line in f:
                parts = dict(p.split("=", 1) for p in line.split()[1:])
                expect = [(int(a), b) for a, b in (e.split(":") for e in parts["expect"].split(",") if e)]
                valid = [int(v) for v in parts["valid"].split(",") if v]
                cls.manifest.append((line.split()[0], int(parts["frames"]), expect, valid))
        cls.dcf = "cop_srdo.dcf:" + os.path.join(cls.dir, "consumer.dcf")

    def test_every_class_has_a_capture(self):
        # twelve of the thirteen classes: the configuration CRC leaves no
        # faulty frame on the bus
        self.assertEqual(len(self.manifest), 12)

    def test_each_fault_reported_at_its_frame_and_nothing_else(self):
        for name, count, expect, valid in self.manifest:
            with self.subTest(capture=name):
                frames = dissect(os.path.join(self.dir, name), self.dcf)
                self.assertEqual(len(frames), count)
                self.assertEqual(error_reports(frames), sorted(expect))
                # every expert info of error severity is one of them
                self.assertEqual(sum(e for _, e, _ in frames.values()), len(expect))
                for n in valid:
                    experts, _, fields = frames[n]
                    self.assertEqual(fields.get("cop_srdo.ok"), "1", f"frame {n}")
                    if not experts:
                        self.assertEqual(fields.get("cop_srdo.status"), "SRDO 1 pair ok", f"frame {n}")

    def test_the_dlc_from_preferences_instead_of_the_dcf(self):
        # wrong DLC without the DCF: with the DLC preference the normal
        # frame is refused at once, without it only the pair's DLCs differ
        name = os.path.join(self.dir, "wrong_dlc.pcap")
        expect = next(e for f, _, e, _ in self.manifest if f == "wrong_dlc.pcap")
        first = expect[0][0]
        with_dlc = dissect(name, "cop_srdo.dlc:4")
        self.assertEqual(error_reports(with_dlc), [(first, "cop_srdo.dlc"), (first + 1, "cop_srdo.order")])
        without = dissect(name)
        self.assertEqual(error_reports(without), [(first + 1, "cop_srdo.dlc")])

    def dcf_with(self, tmp, values):
        """The consumer's DCF with the subindices of 0x1301 in `values` changed."""
        with open(os.path.join(self.dir, "consumer.dcf")) as f:
            text = f.read()
        for sub, value in values.items():
            section = "[1301sub%d]" % sub
            head, tail = text.split(section, 1)
            tail = re.sub(r"ParameterValue=\S+", "ParameterValue=" + value, tail, count=1)
            text = head + section + tail
        path = os.path.join(tmp, "changed.dcf")
        with open(path, "w") as f:
            f.write(text)
        return "cop_srdo.dcf:" + path

    def test_srvt_and_cob_ids_come_from_the_dcf(self):
        name = os.path.join(self.dir, "tick_wrap.pcap")
        with tempfile.TemporaryDirectory() as tmp:
            # SRVT 1 ms in the DCF (the preference stays 20 ms): every
            # inverted frame is late
            frames = dissect(name, self.dcf_with(tmp, {3: "1"}))
            srvt = [n for n, e in error_reports(frames) if e == "cop_srdo.srvt"]
            self.assertEqual(len(srvt), len(frames) // 2)
            # SRDO 1 moved to 0x103/0x104 in the DCF: the frames on
            # 0x101/0x102 belong to no SRDO any more
            frames = dissect(name, self.dcf_with(tmp, {5: "0x103", 6: "0x104"}))
            self.assertEqual([n for n, (_, _, f) in frames.items() if f], [])

    def test_limits_tighter_than_the_traffic_are_reported(self):
        # the fault-free pairs are 2 ms apart and 20 ms from pair to pair:
        # SRVT 1 ms makes every inverted frame late, SCT 19 ms every pair
        name = os.path.join(self.dir, "tick_wrap.pcap")
        frames = dissect(name, "cop_srdo.srvt_ms:1", "cop_srdo.sct_ms:19")
        kinds = {e for _, e in error_reports(frames)}
        self.assertEqual(kinds, {"cop_srdo.srvt"})
        frames = dissect(name, "cop_srdo.sct_ms:19")
        sct = [n for n, e in error_reports(frames) if e == "cop_srdo.sct"]
        self.assertEqual(len(sct), len(frames) // 2 - 1)


def candump_frames(path):
    """(identifier, data bytes) per line of a candump -l log."""
    out = []
    with open(path) as f:
        for line in f:
            m = re.match(r"\(\d+\.\d{6}\) can0 ([0-9A-F]+)#([0-9A-F]*)$", line.strip())
            if m is None:
                raise AssertionError("not a candump -l line: " + line)
            out.append((int(m.group(1), 16), bytes.fromhex(m.group(2))))
    return out


def lonely_normal_frames(log):
    """Frame numbers (from 1) of the normal frames the next normal frame
    follows without an inverted frame in between (SRDO 1: 0x101/0x102)."""
    held = None
    lonely = []
    for i, (ident, _) in enumerate(log, start=1):
        if ident == 0x101:
            if held is not None:
                lonely.append(i)
            held = i
        elif ident == 0x102:
            held = None
    return lonely


def pcap_frames(path):
    """(seconds, identifier word, data) per record of a pcap file of link
    type 227 (pcap format: 24-byte file header, per record 16-byte header;
    struct can_frame: identifier word big-endian, length, 3 bytes, data)."""
    with open(path, "rb") as f:
        raw = f.read()
    magic, major, minor, _, _, _, linktype = struct.unpack("<IHHiIII", raw[:24])
    assert (magic, major, minor, linktype) == (0xA1B2C3D4, 2, 4, 227)
    out = []
    at = 24
    while at < len(raw):
        sec, usec, incl, _ = struct.unpack("<IIII", raw[at:at + 16])
        word, length = struct.unpack(">IB", raw[at + 16:at + 21])
        out.append((sec + usec / 1e6, word, raw[at + 24:at + 24 + length]))
        at += 16 + incl
    return out


def log2asc_frames(log):
    """(relative seconds, identifier, data) of can-utils' log2asc, which
    reads a candump -l log with canplayer's parser."""
    out = subprocess.run(["log2asc", "-I", log, "can0"], check=True, capture_output=True, text=True).stdout
    frames = []
    for line in out.splitlines():
        m = re.match(r"\s*([\d.]+) 1\s+([0-9A-F]+)x?\s+Rx\s+d (\d)((?: [0-9A-F]{2})*)\s*$", line)
        if m:
            frames.append((float(m.group(1)), int(m.group(2), 16), bytes.fromhex(m.group(4))))
    return frames


class SafetyDemo(unittest.TestCase):
    """The C safety demo (scripts/demo.sh) captured with COP_SIM_PCAP."""

    def test_demo_pairs_ok_but_the_injected_loss(self):
        program = os.environ.get("COP_SAFETY_DEMO")
        if not program:
            raise unittest.SkipTest("COP_SAFETY_DEMO not set (scripts/test.sh wireshark sets it)")
        with tempfile.TemporaryDirectory() as tmp:
            pcap = os.path.join(tmp, "demo.pcap")
            log = os.path.join(tmp, "demo.log")
            env = dict(os.environ, COP_SIM_PCAP=pcap, COP_SIM_CANDUMP=log)
            out = subprocess.run([program], check=True, capture_output=True, text=True, env=env).stdout
            # the limits the demo's actuator configures
            m = re.search(r"actuator SRDO 0x1301: direction 2, SCT (\d+) ms, SRVT (\d+) ms", out)
            self.assertIsNotNone(m, out)
            frames = dissect(pcap, "cop_srdo.sct_ms:" + m.group(1), "cop_srdo.srvt_ms:" + m.group(2))
            candump = candump_frames(log)
            self.assertEqual(len(frames), len(candump))
            # the demo loses one inverted frame on purpose: the next normal
            # frame is the one that shows it
            lonely = lonely_normal_frames(candump)
            self.assertEqual(len(lonely), 1)
            self.assertEqual(error_reports(frames), [(lonely[0], "cop_srdo.order")])
            self.assertEqual(sum(e for _, e, _ in frames.values()), 1)
            # the candump log as canplayer reads it holds the frames of the
            # pcap file, with the same times
            pcap_list = pcap_frames(pcap)
            asc = log2asc_frames(log)
            self.assertEqual(len(asc), len(pcap_list))
            t0 = pcap_list[0][0]
            for (t, word, data), (t_asc, ident, data_asc) in zip(pcap_list, asc):
                self.assertEqual((word & 0x1FFFFFFF, data), (ident, data_asc))
                self.assertAlmostEqual(t - t0, t_asc, places=6)
            pairs_ok = [n for n, (_, _, f) in frames.items() if f.get("cop_srdo.status") == "SRDO 1 pair ok"]
            srdo = [n for n, (ident, _) in enumerate(candump, start=1) if ident in (0x101, 0x102)]
            # every SRDO frame is in a valid pair but the lost frame's
            # partner and the frame that reports it
            self.assertEqual(len(pairs_ok), len(srdo) - 2)
            gfc = [n for n, (ident, data) in enumerate(candump, start=1) if ident == 0x001 and not data]
            self.assertTrue(gfc)
            for n in gfc:
                self.assertEqual(frames[n][2].get("cop_srdo.kind"), "GFC")


class RustExamples(unittest.TestCase):
    """The Rust safety sensor and actuator (examples/) captured with COP_SIM_PCAP."""

    def test_every_pair_ok_no_expert_info(self):
        d = os.environ.get("COP_RUST_CAPTURES")
        if not d:
            raise unittest.SkipTest("COP_RUST_CAPTURES not set (scripts/test.sh wireshark sets it)")
        pcaps = sorted(p for p in os.listdir(d) if p.endswith(".pcap"))
        self.assertTrue(pcaps)
        for p in pcaps:
            with self.subTest(capture=p):
                frames = dissect(os.path.join(d, p))
                self.assertEqual(error_reports(frames), [])
                self.assertEqual(sum(e for _, e, _ in frames.values()), 0)
                srdo = [f for _, _, f in frames.values() if f.get("cop_srdo.kind", "").startswith("SRDO")]
                self.assertGreater(len(srdo), 0)
                self.assertTrue(all(f.get("cop_srdo.status", "").endswith("pair ok") for f in srdo))


if __name__ == "__main__":
    unittest.main()
