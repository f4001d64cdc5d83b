"""python-canopen's SDO client against the library's SDO server (CiA 301
7.2.4): expedited, segmented and block transfers of every basic type, of a
long VISIBLE_STRING and of a DOMAIN, and abort codes arriving as
canopen.SdoAbortedError. Values are also checked on the library side
(CcmReadObject, application variables), so both ends agree on the byte
order."""

import binascii
import ctypes
import struct
import unittest

import can
import canopen

import copbus
from peertest import PeerTestCase

# (subindex of 0x2000, struct format, values to write: limits and ordinary ones)
BASIC_TYPES = [
    (1, "<?", [False, True]),
    (2, "<b", [-128, 127, 0, -1]),
    (3, "<h", [-32768, 32767, 0x1234]),
    (4, "<i", [-(2**31), 2**31 - 1, 0x12345678]),
    (5, "<q", [-(2**63), 2**63 - 1, -0x0102030405060708]),
    (6, "<B", [0, 255, 0x5A]),
    (7, "<H", [0, 0xFFFF, 0xA55A]),
    (8, "<I", [0, 0xFFFFFFFF, 0x89ABCDEF]),
    (9, "<Q", [0, 2**64 - 1, 0xFEDCBA9876543210]),
    (10, "<f", [0.0, -1.5, 3.0e38, 1.0e-38]),
    (11, "<d", [0.0, 2.5e-300, -1.0e300, 1.0 / 3.0]),
]


class Transfers(PeerTestCase):
    def test_every_basic_type(self):
        """Writes and reads back each type: python-canopen encodes with the
        EDS type, the library stores the native value (checked with
        CcmReadObject), the upload gives the same value back. Types of up
        to 4 bytes travel expedited, 8-byte types segmented."""
        for sub, fmt, values in BASIC_TYPES:
            var = self.node.sdo[0x2000][sub]
            for value in values:
                with self.subTest(sub=sub, value=value):
                    if fmt in ("<f",):
                        value = struct.unpack(fmt, struct.pack(fmt, value))[0]
                    var.raw = value
                    self.assertEqual(struct.unpack(fmt, self.peer.read(0x2000, sub))[0], value)
                    self.assertEqual(var.raw, value)

    def test_expedited_and_segmented_frames(self):
        """The protocol python-canopen chose is the one expected: expedited
        download/upload (ccs 1 / scs 2, e = 1) for 4 bytes, segmented (e = 0,
        size indicated) for 8 bytes, and a forced segmented download of
        4 bytes is accepted too."""
        self.peer.trace.clear()
        self.node.sdo.download(0x2000, 8, struct.pack("<I", 0x01020304))
        self.node.sdo.download(0x2000, 9, struct.pack("<Q", 0x1122334455667788))
        self.node.sdo.download(0x2000, 8, struct.pack("<I", 0xCAFEF00D), force_segment=True)
        self.assertEqual(self.node.sdo.upload(0x2000, 8), struct.pack("<I", 0xCAFEF00D))
        self.assertEqual(self.node.sdo.upload(0x2000, 9), struct.pack("<Q", 0x1122334455667788))
        requests = [bytes(m.data) for who, m in self.peer.trace if who == "python" and m.arbitration_id == 0x605]
        responses = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x585]
        # expedited download of 4 bytes: 23 00 20 08 04 03 02 01 -> 60 00 20 08
        self.assertEqual(requests[0], bytes([0x23, 0x00, 0x20, 0x08, 0x04, 0x03, 0x02, 0x01]))
        self.assertEqual(responses[0], bytes([0x60, 0x00, 0x20, 0x08, 0, 0, 0, 0]))
        # segmented download of 8 bytes: 21 00 20 09 08 00 00 00, one 7-byte and one 1-byte segment
        self.assertEqual(requests[1], bytes([0x21, 0x00, 0x20, 0x09, 0x08, 0x00, 0x00, 0x00]))
        self.assertEqual(responses[1][:4], bytes([0x60, 0x00, 0x20, 0x09]))
        self.assertEqual(requests[2], bytes([0x00, 0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22]))
        self.assertEqual(responses[2][0], 0x20)
        self.assertEqual(requests[3][:2], bytes([0x1D, 0x11]))  # toggle 1, 6 bytes unused, last
        self.assertEqual(responses[3][0], 0x30)
        # expedited upload response: 43 00 20 08 0D F0 FE CA
        self.assertIn(bytes([0x43, 0x00, 0x20, 0x08, 0x0D, 0xF0, 0xFE, 0xCA]), responses)
        # segmented upload response: 41 00 20 09 08 00 00 00
        self.assertIn(bytes([0x41, 0x00, 0x20, 0x09, 0x08, 0x00, 0x00, 0x00]), responses)

    def test_long_visible_string(self):
        """0x2001 holds up to 256 characters (more than a BYTE tObdSize could
        count): 256, 200, 5 and 1 characters round-trip; the library's
        buffer holds exactly the string."""
        var = self.node.sdo[0x2001]
        for n in (256, 200, 5, 1):
            text = "".join(chr(0x21 + (i * 7 + n) % 94) for i in range(n))
            with self.subTest(length=n):
                var.raw = text
                self.assertEqual(var.raw, text)
                self.assertEqual(self.peer.read(0x2001, 0), text.encode("ascii"))

    def test_segmented_download_without_size(self):
        """python-canopen's stream API writes without stating the size
        (initiate with s = 0); the last segment ends the value."""
        text = "stream " * 30
        self.peer.trace.clear()
        with self.node.sdo.open(0x2001, 0, "wt", encoding="ascii") as f:
            f.write(text)
        initiate = [bytes(m.data) for who, m in self.peer.trace if who == "python" and m.arbitration_id == 0x605][0]
        self.assertEqual(initiate[0], 0x20)
        self.assertEqual(self.node.sdo[0x2001].raw, text)

    def test_string_longer_than_capacity_is_refused(self):
        """257 characters: the size stated at initiate exceeds the object
        (abort 0x06070012, data type length too high); the value is kept."""
        self.node.sdo[0x2001].raw = "kept"
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.node.sdo[0x2001].raw = "x" * 257
        self.assertEqual(cm.exception.code, 0x06070012)
        self.assertEqual(self.node.sdo[0x2001].raw, "kept")

    def test_domain(self):
        """0x2002 is 300 bytes of the application (CcmDefineVarTab): a
        segmented download lands in the C array, the upload returns it."""
        data = bytes((i * 37 + 11) & 0xFF for i in range(300))
        self.node.sdo.download(0x2002, 0, data)
        domain = self.peer.var(ctypes.c_uint8 * 300, "abPeerDomain_g")
        with self.peer.lock:
            self.assertEqual(bytes(domain), data)
        self.assertEqual(self.node.sdo.upload(0x2002, 0), data)
        self.assertEqual(self.node.sdo[0x2002].raw, data)
        # the application changes its data: the next upload sees it
        with self.peer.lock:
            domain[299] = 0x42
        self.assertEqual(self.node.sdo.upload(0x2002, 0)[299], 0x42)
        # a file-like segmented read (python-canopen's stream API) agrees
        with self.node.sdo.open(0x2002, 0, "rb") as f:
            self.assertEqual(f.read()[:299], data[:299])
        # a shorter download: the domain keeps its size and the rest is
        # zero, so no old data remain behind the new value
        self.node.sdo.download(0x2002, 0, b"short")
        self.assertEqual(self.node.sdo.upload(0x2002, 0), b"short" + bytes(295))

    def test_user_defined_variable(self):
        """0x2003 (USERDEF) reads and writes the application's variable."""
        user = self.peer.var(ctypes.c_uint32, "dwPeerUser_g")
        self.node.sdo[0x2003].raw = 0x0BADCAFE
        with self.peer.lock:
            self.assertEqual(user.value, 0x0BADCAFE)
            user.value = 0x12345678
        self.assertEqual(self.node.sdo[0x2003].raw, 0x12345678)

    def test_range_checked_values_inside_the_range(self):
        for sub, values in ((1, (10, 1000, 500)), (2, (-100, 100, 0)), (3, (1, 10))):
            for value in values:
                with self.subTest(sub=sub, value=value):
                    self.node.sdo[0x2020][sub].raw = value
                    self.assertEqual(self.node.sdo[0x2020][sub].raw, value)
        with self.peer.lock:
            self.assertEqual(self.peer.var(ctypes.c_uint8, "bPeerRange_g").value, 10)


class Aborts(PeerTestCase):
    """Each refusal arrives at python-canopen as SdoAbortedError with the
    CiA 301 abort code, and the object keeps its value."""

    def assert_abort(self, code, action):
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            action()
        self.assertEqual(cm.exception.code, code, f"abort 0x{cm.exception.code:08X}, expected 0x{code:08X}")

    def test_object_does_not_exist(self):
        self.assert_abort(0x06020000, lambda: self.node.sdo.upload(0x2FFF, 0))
        self.assert_abort(0x06020000, lambda: self.node.sdo.download(0x2FFF, 0, b"\x01"))
        self.assert_abort(0x06020000, lambda: self.node.sdo.download(0x2FFF, 0, bytes(12)))

    def test_subindex_does_not_exist(self):
        self.assert_abort(0x06090011, lambda: self.node.sdo.upload(0x2000, 0x20))
        self.assert_abort(0x06090011, lambda: self.node.sdo.download(0x2000, 0x20, b"\x01"))
        self.assert_abort(0x06090011, lambda: self.node.sdo.upload(0x1018, 5))

    def test_write_to_read_only(self):
        self.assert_abort(0x06010002, lambda: self.node.sdo.download(0x2010, 1, b"\x00\x00"))
        self.assert_abort(0x06010002, lambda: self.node.sdo.download(0x2010, 3, b"\x00"))
        self.assert_abort(0x06010002, lambda: self.node.sdo.download(0x1000, 0, bytes(4)))
        self.assert_abort(0x06010002, lambda: self.node.sdo.download(0x1008, 0, b"renamed node"))
        self.assert_abort(0x06010002, lambda: self.node.sdo.download(0x2000, 0, b"\x0C"))
        self.assertEqual(self.node.sdo[0x2010][1].raw, 0x1234)
        self.assertEqual(self.node.sdo[0x1008].raw, "cop peer node")

    def test_read_write_only(self):
        self.assert_abort(0x06010001, lambda: self.node.sdo.upload(0x2010, 2))
        self.node.sdo[0x2010][2].raw = 0x11223344  # writing it is fine
        # the application's CcmReadObject obeys the same access right
        with self.assertRaises(copbus.CopError) as cm:
            self.peer.read(0x2010, 2)
        self.assertEqual(cm.exception.code, 0x0033)  # kCopObdReadViolation

    def test_length_does_not_match(self):
        """A value whose length differs from the type: 0x0607001x (CiA 301:
        0x06070010 in general, ...12 too long, ...13 too short)."""
        cases = [
            (0x2000, 7, b"\x01\x02\x03", 0x06070012),  # 3 bytes for UNSIGNED16
            (0x2000, 8, b"\x01\x02", 0x06070013),  # 2 bytes for UNSIGNED32
            (0x2000, 9, bytes(4), 0x06070013),  # 4 bytes for UNSIGNED64
            (0x2000, 6, bytes(8), 0x06070012),  # segmented 8 bytes for UNSIGNED8
        ]
        for index, sub, data, code in cases:
            with self.subTest(sub=sub, length=len(data)):
                self.assert_abort(code, lambda: self.node.sdo.download(index, sub, data))
        self.assertEqual(self.node.sdo[0x2000][7].raw, 0xB16B)

    def test_value_range(self):
        cases = [
            (1, 1001, 0x06090031),
            (1, 9, 0x06090032),
            (2, 101, 0x06090031),
            (2, -101, 0x06090032),
            (3, 11, 0x06090031),
            (3, 0, 0x06090032),
        ]
        for sub, value, code in cases:
            with self.subTest(sub=sub, value=value):
                fmt = {1: "<H", 2: "<h", 3: "<B"}[sub]
                self.assert_abort(code, lambda: self.node.sdo.download(0x2020, sub, struct.pack(fmt, value)))
        self.assertEqual(self.node.sdo[0x2020][1].raw, 100)
        self.assertEqual(self.node.sdo[0x2020][2].raw, 0)
        self.assertEqual(self.node.sdo[0x2020][3].raw, 5)

    def test_boolean_above_one(self):
        self.assert_abort(0x06090031, lambda: self.node.sdo.download(0x2000, 1, b"\x02"))
        self.assertEqual(self.node.sdo[0x2000][1].raw, True)

    def test_abort_carries_the_multiplexer(self):
        """The abort frame names the object of the request (CiA 301 7.2.4.3.17)."""
        self.peer.trace.clear()
        self.assert_abort(0x06090011, lambda: self.node.sdo.upload(0x2000, 0x20))
        aborts = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x585]
        self.assertEqual(aborts, [bytes([0x80, 0x00, 0x20, 0x20, 0x11, 0x00, 0x09, 0x06])])


class Emergency(PeerTestCase):
    def test_emergency_reaches_python_canopen(self):
        """CcmSendEmergency: python-canopen's EMCY consumer (0x80 + node-ID)
        decodes error code, error register and manufacturer bytes."""
        self.peer.send_emergency(0x8130, 0x11, b"\x01\x02\x03\x04\x05")
        err = self.node.emcy.wait(0x8130, timeout=2)
        self.assertIsNotNone(err, "no EMCY received")
        self.assertEqual(err.code, 0x8130)
        self.assertEqual(err.register, 0x11)
        self.assertEqual(err.data, b"\x01\x02\x03\x04\x05")
        frames = [m for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x85]
        self.assertEqual(len(frames), 1)



class BlockTransfers(PeerTestCase):
    """python-canopen's block client (CiA 301 SDO block download and block
    upload, with CRC) against the server."""

    def test_block_download(self):
        """python-canopen's block download (CiA 301 SDO block download:
        initiate with size and CRC support, sub-blocks of the block size the
        server grants, end with n and CRC) of a 256-character string and of
        the 300-byte domain; the value arrives whole (one write)."""
        text = bytes(0x21 + (i * 11) % 94 for i in range(256))
        self.peer.trace.clear()
        with self.node.sdo.open(0x2001, 0, "wb", size=len(text), block_transfer=True) as f:
            f.write(text)
        self.assertEqual(self.peer.read(0x2001, 0), text)
        requests = [bytes(m.data) for who, m in self.peer.trace if who == "python" and m.arbitration_id == 0x605]
        responses = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x585]
        # C6 = ccs 6, cc, s; size 256. A4 = scs 5, sc; blksize in byte 4.
        self.assertEqual(requests[0], bytes([0xC6, 0x01, 0x20, 0x00, 0x00, 0x01, 0x00, 0x00]))
        self.assertEqual(responses[0][:4], bytes([0xA4, 0x01, 0x20, 0x00]))
        blksize = responses[0][4]
        self.assertTrue(1 <= blksize <= 127)
        # 37 segments in sub-blocks of blksize, each confirmed with A2 ackseq blksize
        segments = (256 + 6) // 7
        acks = [r for r in responses if r[0] == 0xA2]
        self.assertEqual(len(acks), (segments + blksize - 1) // blksize)
        self.assertTrue(all(a[2] == blksize for a in acks))
        # end: C1 | n << 2 (n = 3 -> CD) with the CRC-16 (XMODEM) of the data; A1
        end = requests[-1]
        self.assertEqual(end[0], 0xCD)
        self.assertEqual(struct.unpack_from("<H", end, 1)[0], binascii.crc_hqx(text, 0))
        self.assertEqual(responses[-1], bytes([0xA1, 0, 0, 0, 0, 0, 0, 0]))

        data = bytes((i * 29 + 3) & 0xFF for i in range(300))
        with self.node.sdo.open(0x2002, 0, "wb", size=len(data), block_transfer=True) as f:
            f.write(data)
        domain = self.peer.var(ctypes.c_uint8 * 300, "abPeerDomain_g")
        with self.peer.lock:
            self.assertEqual(bytes(domain), data)

    def test_block_upload(self):
        """python-canopen's block upload (blksize 127, pst 0, CRC) of the
        300-byte domain, of a string and of a 4-byte value: the server sends
        its snapshot in sub-blocks and ends with n and the CRC, which
        python-canopen checks."""
        data = bytes((i * 53 + 1) & 0xFF for i in range(300))
        self.node.sdo.download(0x2002, 0, data)
        self.peer.trace.clear()
        with self.node.sdo.open(0x2002, 0, "rb", block_transfer=True) as f:
            self.assertEqual(f.read(), data)
        requests = [bytes(m.data) for who, m in self.peer.trace if who == "python" and m.arbitration_id == 0x605]
        responses = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x585]
        # A4 = ccs 5, cc; blksize 127, pst 0 -> C6 = scs 6, sc, s; size 300 (2C 01)
        self.assertEqual(requests[0], bytes([0xA4, 0x02, 0x20, 0x00, 0x7F, 0x00, 0x00, 0x00]))
        self.assertEqual(responses[0], bytes([0xC6, 0x02, 0x20, 0x00, 0x2C, 0x01, 0x00, 0x00]))
        self.assertEqual(requests[1], bytes([0xA3, 0, 0, 0, 0, 0, 0, 0]))
        # 43 segments in one sub-block, the last with c = 1; confirmation A2 2B 7F
        segments = responses[1:-1]
        self.assertEqual([r[0] for r in segments], list(range(1, 43)) + [0x80 | 43])
        self.assertIn(bytes([0xA2, 43, 0x7F, 0, 0, 0, 0, 0]), requests)
        # end request: n = 1 -> C5, CRC; the end response A1
        self.assertEqual(responses[-1][0], 0xC5)
        self.assertEqual(struct.unpack_from("<H", responses[-1], 1)[0], binascii.crc_hqx(data, 0))
        self.assertEqual(requests[-1], bytes([0xA1, 0, 0, 0, 0, 0, 0, 0]))

        text = b"block upload of a string"
        self.node.sdo[0x2001].raw = text.decode("ascii")
        with self.node.sdo.open(0x2001, 0, "rb", block_transfer=True) as f:
            self.assertEqual(f.read(), text)
        with self.node.sdo.open(0x2000, 8, "rb", block_transfer=True) as f:
            self.assertEqual(f.read(), struct.pack("<I", 0xC0FFEE32))
        # the server is ready for the next transfer
        self.assertEqual(self.node.sdo[0x1000].raw, 0x00030191)

    def test_block_transfer_refusals(self):
        """Block requests the server refuses get the dictionary's or the
        protocol's abort, which python-canopen raises."""
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            with self.node.sdo.open(0x2FFF, 0, "rb", block_transfer=True) as f:
                f.read()
        self.assertEqual(cm.exception.code, 0x06020000)
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            with self.node.sdo.open(0x2010, 1, "wb", size=2, block_transfer=True) as f:
                f.write(b"\x01\x02")
        self.assertEqual(cm.exception.code, 0x06010002)
        # 257 characters into the 256-character string: 0x06070012
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            with self.node.sdo.open(0x2001, 0, "wb", size=257, block_transfer=True) as f:
                f.write(b"x" * 257)
        self.assertEqual(cm.exception.code, 0x06070012)
        self.assertEqual(self.node.sdo[0x1000].raw, 0x00030191)


if __name__ == "__main__":
    unittest.main()


class SecondServer(PeerTestCase):
    """The additional SDO server 0x1201 (CiA 301 7.5.2.33), delivered
    without COB-IDs: python-canopen gives it its identifiers over the
    default server and then uses it as a second SDO channel of its own
    (RemoteNode.add_sdo), as a configuration tool beside the master would."""

    RX, TX = 0x641, 0x5C1  # client to server, server to client

    def channel(self):
        second = self.node.add_sdo(self.RX, self.TX)
        # add_sdo subscribes the channel but leaves its network unset
        second.network = self.network
        return second

    def test_second_channel_after_configuration(self):
        second = self.channel()
        # delivered with bit 31 set: the server does not exist (that nothing
        # answers then is checked frame by frame in c_tests/test_sdo_servers.c)
        self.assertEqual(self.node.sdo[0x1201][1].raw, 0x80000000)
        self.node.sdo[0x1201][1].raw = self.RX
        self.node.sdo[0x1201][2].raw = self.TX
        self.node.sdo[0x1201][3].raw = 0x7F
        self.assertEqual(self.node.sdo[0x1201][1].raw, self.RX)

        self.peer.trace.clear()
        self.assertEqual(second.upload(0x1000, 0), struct.pack("<I", 0x00030191))
        requests = [bytes(m.data) for who, m in self.peer.trace if who == "python" and m.arbitration_id == self.RX]
        responses = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == self.TX]
        # CiA 301 7.2.4.3.6: initiate upload 0x40, expedited answer 0x43
        self.assertEqual(requests, [bytes([0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0])])
        self.assertEqual(responses, [bytes([0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x03, 0x00])])

        # segmented and block transfers on the second channel, the default
        # channel still serving in between
        second[0x2001].raw = "written over the second server"
        self.assertEqual(self.node.sdo[0x2001].raw, "written over the second server")
        text = bytes(0x30 + i % 40 for i in range(200))
        with second.open(0x2001, 0, "wb", size=len(text), block_transfer=True) as f:
            f.write(text)
        self.assertEqual(self.peer.read(0x2001, 0), text)
        with second.open(0x2001, 0, "rb", block_transfer=True) as f:
            self.assertEqual(f.read(), text)
        self.assertEqual(self.node.sdo[0x1000].raw, 0x00030191)

        # bit 31 again: the channel is gone, the default one stays
        self.peer.trace.clear()
        self.node.sdo[0x1201][1].raw = 0x80000000 | self.RX
        self.peer.inject(can.Message(arbitration_id=self.RX, data=bytes([0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0]), is_extended_id=False))
        self.assertEqual(self.node.sdo[0x1000].raw, 0x00030191)
        answers = [m for who, m in self.peer.trace if who == "node" and m.arbitration_id == self.TX]
        self.assertEqual(answers, [])

    def test_identifiers_of_other_services_are_refused(self):
        """The same rule as for every SDO COB-ID: no SRDO or NMT identifier
        (abort 0x06090030), and the object keeps its value."""
        for cob in (0x109, 0x000, 0x701):
            with self.subTest(cob=hex(cob)):
                with self.assertRaises(canopen.SdoAbortedError) as cm:
                    self.node.sdo[0x1201][1].raw = cob
                self.assertEqual(cm.exception.code, 0x06090030)
        self.assertEqual(self.node.sdo[0x1201][1].raw, 0x80000000)
