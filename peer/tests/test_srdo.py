"""SRDO (CiA 304) configured by python-canopen over SDO, the way a safety
configurator does it: communication parameters and mapping while the SRDO
is disabled, then the direction, the checksum (computed here from the
definition, cia304.py) and 0xA5 to 0x13FE; then NMT start. The library
must then produce the normal/inverted frame pair python sees on its bus,
consume a pair python sends, and refuse what CiA 304 forbids with the
documented SDO abort codes."""

import ctypes
import threading
import time
import unittest

import canopen

import copbus
from cia304 import crc16_xmodem, srdo_crc, srdo_crc_stream
from peertest import PeerTestCase

SRDO = 0x1301
COB1, COB2 = 0x109, 0x10A  # predefined connection set of node 5
RX_COB1, RX_COB2 = 0x10B, 0x10C  # a producer with node-ID 6
TX_MAPPING = [0x20300108, 0x20310108, 0x20300210, 0x20310210]
RX_MAPPING = [0x20400108, 0x20410108, 0x20400210, 0x20410210]


class Crc(unittest.TestCase):
    def test_definition_against_public_vectors(self):
        """The Python CRC itself, on the vectors of SAFETY_BEHAVIOUR section 3."""
        self.assertEqual(crc16_xmodem(b"123456789"), 0x31C3)
        stream = srdo_crc_stream(1, 25, 20, 0x101, 0x102, [0x62000108, 0x62000208])
        self.assertEqual(
            stream.hex(" "), "01 19 00 14 01 01 00 00 02 01 00 00 02 01 08 01 00 62 02 08 02 00 62"
        )
        vectors = [
            (1, [0x62000108, 0x62000208], 0xD879),
            (2, [0x62000108, 0x62000208], 0x7764),
            (1, [0x62000108, 0x62000208, 0x62000308, 0x62000408], 0xE57E),
            (1, [0x63000110, 0x63000210, 0x62000108, 0x62000208], 0x25EA),
            (2, [0x63000110, 0x63000210, 0x62000108, 0x62000208], 0xA3AF),
        ]
        for direction, mapping, crc in vectors:
            self.assertEqual(srdo_crc(direction, 25, 20, 0x101, 0x102, mapping), crc)


class SrdoTestCase(PeerTestCase):
    def setUp(self):
        super().setUp()
        self.frames = []
        self.frames_lock = threading.Lock()
        for cob in (COB1, COB2):
            self.network.subscribe(cob, self._on_srdo_frame)

    def _on_srdo_frame(self, can_id, data, timestamp):
        with self.frames_lock:
            self.frames.append((can_id, bytes(data)))

    def taken_frames(self):
        with self.frames_lock:
            out, self.frames = self.frames, []
            return out

    def configure(self, direction, sct, srvt, cob1, cob2, mapping, crc=None):
        """Writes the SRDO over SDO in the CiA 304 order and returns the CRC
        computed here (written unless crc is given)."""
        sdo = self.node.sdo
        sdo[SRDO][1].raw = 0
        sdo[SRDO][2].raw = sct
        sdo[SRDO][3].raw = srvt
        sdo[SRDO][5].raw = cob1
        sdo[SRDO][6].raw = cob2
        sdo[0x1381][0].raw = 0
        for sub, entry in enumerate(mapping, start=1):
            sdo[0x1381][sub].raw = entry
        sdo[0x1381][0].raw = len(mapping)
        sdo[SRDO][1].raw = direction
        computed = srdo_crc(direction, sct, srvt, cob1, cob2, mapping)
        self.assertEqual(self.peer.calc_srdo_crc(SRDO), computed, "CcmCalcSrdoCrc differs from CiA 304")
        sdo[0x13FF][1].raw = computed if crc is None else crc
        return computed

    def start(self):
        self.node.nmt.state = "OPERATIONAL"
        self.wait_until(lambda: self.peer.node_state() == copbus.STATE_OPERATIONAL, what="OPERATIONAL")


class Transmit(SrdoTestCase):
    def setUp(self):
        super().setUp()
        self.configure(1, 50, 20, COB1, COB2, TX_MAPPING)
        self.node.sdo[0x13FE].raw = 0xA5
        self.assertEqual(self.node.sdo[0x13FE].raw, 0xA5)
        self.assertEqual(self.peer.check_srdo_config(), (copbus.K_SUCCESSFUL, 0))

    def set_outputs(self, b, w, b_inv, w_inv):
        """The master writes the safe outputs over SDO (in any NMT state)."""
        self.node.sdo[0x2030][1].raw = b
        self.node.sdo[0x2030][2].raw = w
        self.node.sdo[0x2031][1].raw = b_inv
        self.node.sdo[0x2031][2].raw = w_inv

    def test_pair_on_the_bus(self):
        self.set_outputs(0x5A, 0x1234, 0xA5, 0xEDCB)
        self.start()
        time.sleep(0.01)  # first transmission: 0.5 ms x node-ID after the start
        self.taken_frames()
        self.peer.take_events()
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SUCCESSFUL)
        frames = self.wait_until(lambda: len(self.frames) >= 2 and self.taken_frames(), what="SRDO pair")
        self.assertEqual(frames, [(COB1, bytes([0x5A, 0x34, 0x12])), (COB2, bytes([0xA5, 0xCB, 0xED]))])
        normal, inverted = frames[0][1], frames[1][1]
        self.assertEqual(bytes(b ^ 0xFF for b in normal), inverted)
        self.assertIn(copbus.Event(copbus.EV_SRDO, 0, SRDO, 0), self.peer.take_events())
        self.assertEqual(self.peer.srdo_state(SRDO) & 0x30, 0x00)

        # new values from the master, a second pair
        self.set_outputs(0x00, 0xFFFF, 0xFF, 0x0000)
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SUCCESSFUL)
        frames = self.wait_until(lambda: len(self.frames) >= 2 and self.taken_frames(), what="second pair")
        self.assertEqual(frames, [(COB1, bytes([0x00, 0xFF, 0xFF])), (COB2, bytes([0xFF, 0x00, 0x00]))])

    def test_inverted_data_not_complement(self):
        """CcmSendSrdo checks bit by bit before sending: nothing reaches the
        bus, AppSrdoError reports kCopSrdoDataError."""
        self.set_outputs(0x5A, 0x1234, 0xA5, 0xEDCA)
        self.start()
        time.sleep(0.01)
        self.peer.take_events()
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SRDO_DATA_ERROR)
        time.sleep(0.05)
        self.assertEqual(self.taken_frames(), [])
        errors = self.peer.take_events(copbus.EV_SRDO_ERROR)
        self.assertIn(copbus.Event(copbus.EV_SRDO_ERROR, 0, SRDO, copbus.K_SRDO_DATA_ERROR), errors)

    def test_not_sent_before_operational(self):
        self.set_outputs(0x5A, 0x1234, 0xA5, 0xEDCB)
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SRDO_NMT_ERROR)
        time.sleep(0.05)
        self.assertEqual(self.taken_frames(), [])

    def test_parameters_locked_in_operational(self):
        """CiA 304: SRDO parameters cannot be written in OPERATIONAL (abort
        0x08000022); the configuration stays valid and the SRDO keeps
        working."""
        self.start()
        writes = [
            (SRDO, 1, 0),
            (SRDO, 2, 100),
            (SRDO, 3, 30),
            (SRDO, 5, 0x111),
            (SRDO, 6, 0x112),
            (0x1381, 0, 0),
            (0x1381, 1, 0x20300108),
            (0x13FF, 1, 0x1234),
        ]
        for index, sub, value in writes:
            with self.subTest(object=f"0x{index:04X}/{sub}"):
                with self.assertRaises(canopen.SdoAbortedError) as cm:
                    self.node.sdo[index][sub].raw = value
                self.assertEqual(cm.exception.code, 0x08000022)
        self.assertEqual(self.node.sdo[0x13FE].raw, 0xA5)
        self.assertEqual(self.node.sdo[SRDO][2].raw, 50)
        self.set_outputs(0x01, 0x0203, 0xFE, 0xFDFC)
        time.sleep(0.01)
        self.taken_frames()
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SUCCESSFUL)
        frames = self.wait_until(lambda: len(self.frames) >= 2 and self.taken_frames(), what="SRDO pair")
        self.assertEqual(frames, [(COB1, bytes([0x01, 0x03, 0x02])), (COB2, bytes([0xFE, 0xFC, 0xFD]))])


class Configuration(SrdoTestCase):
    def test_wrong_crc_is_refused(self):
        """0xA5 with a checksum that does not match: abort 0x08000020, 0x13FE
        stays invalid, CcmCheckSrdoConfig names the SRDO, and after NMT start
        nothing is sent."""
        crc = self.configure(1, 50, 20, COB1, COB2, TX_MAPPING, crc=None)
        self.node.sdo[0x13FF][1].raw = crc ^ 0x0001
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[0x13FE].raw = 0xA5
        self.assertEqual(cm.exception.code, 0x08000020)
        self.assertEqual(self.node.sdo[0x13FE].raw, 0x00)
        self.assertEqual(self.peer.check_srdo_config(), (copbus.K_SRDO_CFG_CRC_ERROR, SRDO))
        self.start()
        time.sleep(0.01)
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SRDO_INVALID_CFG)
        time.sleep(0.05)
        self.assertEqual(self.taken_frames(), [])
        # the right checksum makes it valid (in PRE-OPERATIONAL again)
        self.node.nmt.state = "PRE-OPERATIONAL"
        self.wait_until(lambda: self.peer.node_state() == copbus.STATE_PRE_OPERATIONAL, what="PRE-OPERATIONAL")
        self.node.sdo[0x13FF][1].raw = crc
        self.node.sdo[0x13FE].raw = 0xA5
        self.assertEqual(self.node.sdo[0x13FE].raw, 0xA5)

    def test_a_parameter_write_invalidates_the_configuration(self):
        """Any write to an SRDO parameter sets 0x13FE to 0 (SAFETY_BEHAVIOUR 2)."""
        self.configure(1, 50, 20, COB1, COB2, TX_MAPPING)
        self.node.sdo[0x13FE].raw = 0xA5
        self.node.sdo[SRDO][2].raw = 60
        self.assertEqual(self.node.sdo[0x13FE].raw, 0x00)
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[0x13FE].raw = 0xA5  # the stored checksum no longer matches
        self.assertEqual(cm.exception.code, 0x08000020)

    def test_parameter_rules(self):
        """Values CiA 304 does not allow are refused with an abort, never stored."""
        self.configure(1, 50, 20, COB1, COB2, TX_MAPPING)
        # COB-ID and mapping only while the SRDO is disabled (direction 0):
        # abort 0x06090030 (SAFETY_BEHAVIOUR 2 leaves 0x06090030 or 0x08000022 to the library)
        for index, sub, value in ((SRDO, 5, 0x111), (SRDO, 6, 0x112), (0x1381, 1, 0x20310108), (0x1381, 0, 2)):
            with self.subTest(object=f"0x{index:04X}/{sub}"):
                with self.assertRaises(canopen.SdoAbortedError) as cm:
                    self.node.sdo[index][sub].raw = value
                self.assertEqual(cm.exception.code, 0x06090030)
        self.assertEqual(self.node.sdo[SRDO][5].raw, COB1)
        # the value in force is no change (manual 1.1.1): accepted
        self.node.sdo[SRDO][5].raw = COB1
        self.node.sdo[0x1381][1].raw = TX_MAPPING[0]
        self.assertEqual(self.node.sdo[0x13FE].raw, 0x00)
        # direction other than 0, 1, 2
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[SRDO][1].raw = 3
        self.assertEqual(cm.exception.code, 0x06090030)
        self.assertEqual(self.node.sdo[SRDO][1].raw, 1)
        # transmission type is constant (254)
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[SRDO][4].raw = 253
        self.assertEqual(cm.exception.code, 0x06010002)
        self.assertEqual(self.node.sdo[SRDO][4].raw, 254)

    def test_mapping_writes_are_checked_at_once(self):
        """Manual 2.5: each mapping write is checked; the abort names the reason
        (CiA 301 table 22), nothing is stored."""
        self.configure(1, 50, 20, COB1, COB2, TX_MAPPING)
        self.node.sdo[SRDO][1].raw = 0
        self.node.sdo[0x1381][0].raw = 0
        for sub, value, code in (
            (1, 0x30000110, 0x06020000),  # object does not exist
            (1, 0x20300908, 0x06090011),  # subindex does not exist
            (1, 0x13010210, 0x06040041),  # SCT: cannot be mapped
        ):
            with self.subTest(entry=f"0x{value:08X}"):
                with self.assertRaises(canopen.SdoAbortedError) as cm:
                    self.node.sdo[0x1381][sub].raw = value
                self.assertEqual(cm.exception.code, code)
                self.assertEqual(self.node.sdo[0x1381][sub].raw, TX_MAPPING[sub - 1])
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[0x1381][0].raw = 3  # an odd count
        self.assertEqual(cm.exception.code, 0x06040043)
        self.assertEqual(self.node.sdo[0x1381][0].raw, 0)
        self.node.sdo[0x1381][0].raw = 4


class Receive(SrdoTestCase):
    def setUp(self):
        super().setUp()
        self.configure(2, 500, 20, RX_COB1, RX_COB2, RX_MAPPING)
        self.node.sdo[0x13FE].raw = 0xA5
        self.start()
        self.peer.take_events()

    def inputs(self):
        with self.peer.lock:
            return (
                self.peer.var(ctypes.c_uint8, "bPeerSafeIn_g").value,
                self.peer.var(ctypes.c_uint16, "wPeerSafeIn_g").value,
                self.peer.var(ctypes.c_uint8, "bPeerSafeInInv_g").value,
                self.peer.var(ctypes.c_uint16, "wPeerSafeInInv_g").value,
            )

    def test_valid_pair_reaches_the_variables(self):
        self.network.send_message(RX_COB1, bytes([0x3C, 0x78, 0x56]))
        self.network.send_message(RX_COB2, bytes([0xC3, 0x87, 0xA9]))
        self.assertEqual(self.inputs(), (0x3C, 0x5678, 0xC3, 0xA987))
        self.assertEqual(self.peer.take_events(copbus.EV_SRDO), [copbus.Event(copbus.EV_SRDO, 0, SRDO, 0)])
        self.assertEqual(self.peer.take_events(copbus.EV_SRDO_ERROR), [])

    def test_faulty_pairs_are_reported_and_not_used(self):
        self.network.send_message(RX_COB1, bytes([0x3C, 0x78, 0x56]))
        self.network.send_message(RX_COB2, bytes([0xC3, 0x87, 0xA9]))
        self.peer.take_events()
        # inverted frame not the complement
        self.network.send_message(RX_COB1, bytes([0x01, 0x00, 0x00]))
        self.network.send_message(RX_COB2, bytes([0x00, 0xFF, 0xFF]))
        # inverted frame without normal frame
        self.network.send_message(RX_COB2, bytes([0xFE, 0xFF, 0xFF]))
        # inverted frame later than SRVT (20 ms)
        self.network.send_message(RX_COB1, bytes([0x02, 0x00, 0x00]))
        self.peer.advance_ms(30)
        self.network.send_message(RX_COB2, bytes([0xFD, 0xFF, 0xFF]))
        errors = [e.code for e in self.peer.take_events(copbus.EV_SRDO_ERROR)]
        self.assertEqual(errors, [copbus.K_SRDO_DATA_ERROR, copbus.K_SRDO_NOT_IN_ORDER, 0x010D])
        self.assertEqual(self.inputs(), (0x3C, 0x5678, 0xC3, 0xA987))
        self.assertEqual(self.peer.take_events(copbus.EV_SRDO), [])

    def test_sct_timeout_when_the_producer_stops(self):
        self.network.send_message(RX_COB1, bytes([0x3C, 0x78, 0x56]))
        self.network.send_message(RX_COB2, bytes([0xC3, 0x87, 0xA9]))
        errors = self.wait_until(
            lambda: self.peer.take_events(copbus.EV_SRDO_ERROR), timeout=3.0, what="SCT timeout"
        )
        self.assertEqual([e.code for e in errors], [copbus.K_SRDO_SCT_TIMEOUT])

    def test_global_fail_safe_command(self):
        """GFC (id 0x001, DLC 0) reaches AppGfcEvent only while 0x1300 = 1;
        0x1300 itself is written by python-canopen in PRE-OPERATIONAL."""
        self.network.send_message(0x001, b"")
        time.sleep(0.02)
        self.assertEqual(self.peer.take_events(copbus.EV_GFC), [])
        self.node.nmt.state = "PRE-OPERATIONAL"
        self.wait_until(lambda: self.peer.node_state() == copbus.STATE_PRE_OPERATIONAL, what="PRE-OPERATIONAL")
        self.node.sdo[0x1300].raw = 1
        self.start()
        self.network.send_message(0x001, b"")
        self.wait_until(lambda: self.peer.take_events(copbus.EV_GFC), what="AppGfcEvent")


if __name__ == "__main__":
    unittest.main()
