"""The library's SDO client (CcmSdocDefineClientTab, CcmSdocStartTransfer,
CcmSdocGetState, SdocGetTransmittedBytes) against python-canopen's SDO
server (a LocalNode with node-ID 0x22): expedited and segmented upload and
download, block requests (python-canopen 2.4.1's server answers a block
upload with the SDO upload protocol and refuses a block download), and the
server's aborts reported by CcmSdocGetState."""

import struct
import unittest

from canopen import objectdictionary as od
from canopen.objectdictionary import datatypes

import copbus
from peertest import PeerTestCase

SERVER_ID = 0x22
CLIENT = 0x1280

# tSdocState (cop_types.h)
NOT_ACTIVE, RUNNING, TX_ABORTED, RX_ABORTED, FINISHED = 0, 1, 2, 3, 4


def server_dictionary():
    """The LocalNode's dictionary: a few objects of each kind."""
    d = od.ObjectDictionary()

    def var(index, sub, name, data_type, access, default=None, parent=None):
        v = od.ODVariable(name, index, sub)
        v.data_type = data_type
        v.access_type = access
        v.default = default
        if parent is None:
            d.add_object(v)
        else:
            parent.add_member(v)
        return v

    var(0x1017, 0, "Producer heartbeat time", datatypes.UNSIGNED16, "rw", 0)
    var(0x2100, 0, "UNSIGNED32", datatypes.UNSIGNED32, "rw", 0x01020304)
    var(0x2101, 0, "Text", datatypes.VISIBLE_STRING, "rw", "")
    var(0x2102, 0, "Blob", datatypes.DOMAIN, "rw", b"")
    var(0x2103, 0, "Read-only", datatypes.UNSIGNED16, "ro", 0x0BEE)
    var(0x2104, 0, "Write-only", datatypes.UNSIGNED8, "wo", 0)
    rec = od.ODRecord("Record", 0x2105)
    var(0x2105, 0, "Highest sub-index supported", datatypes.UNSIGNED8, "const", 1, rec)
    var(0x2105, 1, "Value", datatypes.INTEGER16, "rw", -7, rec)
    d.add_object(rec)
    return d


class SdoClient(PeerTestCase):
    def setUp(self):
        super().setUp()
        self.server = self.network.create_node(SERVER_ID, server_dictionary())
        self.peer.sdoc_define(SERVER_ID, 0x600 + SERVER_ID, 0x580 + SERVER_ID, 1000)
        self.peer.take_events()

    def transfer(self, index, sub, upload, data=b"", length=None, block=False):
        """Runs one transfer to its end; returns (state, abort code)."""
        self.peer.sdoc_start(index, sub, upload, data, length, block)
        result = self.wait_until(
            lambda: (lambda s: s if s[0] != RUNNING else None)(self.peer.sdoc_state()), what="end of transfer"
        )
        finished = self.peer.take_events(copbus.EV_SDOC)
        self.assertEqual(
            finished, [copbus.Event(copbus.EV_SDOC, result[0], CLIENT, result[1])], "finish callback"
        )
        return result

    def client_frames(self):
        return [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x600 + SERVER_ID]

    def test_expedited_upload(self):
        self.server.set_data(0x2100, 0, struct.pack("<I", 0x89ABCDEF))
        self.assertEqual(self.transfer(0x2100, 0, True, length=4), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_bytes(), 4)
        self.assertEqual(self.peer.sdoc_data(4), struct.pack("<I", 0x89ABCDEF))
        self.assertEqual(self.client_frames(), [bytes([0x40, 0x00, 0x21, 0x00, 0, 0, 0, 0])])

    def test_expedited_download(self):
        self.assertEqual(self.transfer(0x2100, 0, False, struct.pack("<I", 0xFEEDBEEF)), (FINISHED, 0))
        self.assertEqual(self.server.sdo[0x2100].raw, 0xFEEDBEEF)
        self.assertEqual(self.client_frames(), [bytes([0x23, 0x00, 0x21, 0x00, 0xEF, 0xBE, 0xED, 0xFE])])
        self.assertEqual(self.transfer(0x2105, 1, False, struct.pack("<h", -300)), (FINISHED, 0))
        self.assertEqual(self.server.sdo[0x2105][1].raw, -300)

    def test_segmented_download(self):
        text = "".join(chr(0x41 + i % 26) for i in range(200))
        self.assertEqual(self.transfer(0x2101, 0, False, text.encode("ascii")), (FINISHED, 0))
        self.assertEqual(self.server.sdo[0x2101].raw, text)
        frames = self.client_frames()
        self.assertEqual(frames[0], bytes([0x21, 0x01, 0x21, 0x00, 200, 0, 0, 0]))
        self.assertEqual(len(frames), 1 + (200 + 6) // 7)
        self.assertEqual(frames[-1][0] & 0x01, 0x01, "last segment without c bit")

    def test_segmented_upload(self):
        blob = bytes((i * 13 + 5) & 0xFF for i in range(250))
        self.server.set_data(0x2102, 0, blob)
        self.assertEqual(self.transfer(0x2102, 0, True, length=1024), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_bytes(), 250)
        self.assertEqual(self.peer.sdoc_data(250), blob)
        frames = self.client_frames()
        self.assertEqual(frames[0], bytes([0x40, 0x02, 0x21, 0x00, 0, 0, 0, 0]))
        self.assertEqual([f[0] for f in frames[1:]], [0x60 | (0x10 * (i % 2)) for i in range(len(frames) - 1)])

    def test_block_upload_follows_the_protocol_switch(self):
        """kSdocTypeBlockUp: the client asks for a block upload (A4 = ccs 5
        with CRC support, blksize, pst 0); python-canopen's server answers
        with the SDO upload protocol instead, which CiA 301 lets a server
        do, and the client completes the transfer that way (segmented for
        250 bytes, expedited for 4)."""
        blob = bytes((i * 7 + 3) & 0xFF for i in range(250))
        self.server.set_data(0x2102, 0, blob)
        self.assertEqual(self.transfer(0x2102, 0, True, length=1024, block=True), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_bytes(), 250)
        self.assertEqual(self.peer.sdoc_data(250), blob)
        frames = self.client_frames()
        self.assertEqual(frames[0][:4], bytes([0xA4, 0x02, 0x21, 0x00]))
        self.assertTrue(1 <= frames[0][4] <= 127, "blksize")
        self.assertEqual(frames[0][5], 0, "pst")
        self.assertEqual([f[0] for f in frames[1:]], [0x60 | (0x10 * (i % 2)) for i in range(len(frames) - 1)])
        self.server.set_data(0x2100, 0, struct.pack("<I", 0x11223344))
        self.assertEqual(self.transfer(0x2100, 0, True, length=4, block=True), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_data(4), struct.pack("<I", 0x11223344))

    def test_block_download_refused_by_the_server(self):
        """kSdocTypeBlockDown: the initiate (C6 = ccs 6, CRC support, size)
        goes out; python-canopen 2.4.1's server has no block download and
        aborts with 0x05040001, which the client reports."""
        text = b"block download " * 4
        self.assertEqual(self.transfer(0x2101, 0, False, text, block=True), (RX_ABORTED, 0x05040001))
        self.assertEqual(self.client_frames()[0], bytes([0xC6, 0x01, 0x21, 0x00, len(text), 0, 0, 0]))
        # the channel is free again
        self.assertEqual(self.transfer(0x2101, 0, False, text), (FINISHED, 0))
        self.assertEqual(self.server.sdo[0x2101].raw, text.decode("ascii"))

    def test_aborts_of_the_server(self):
        """python-canopen's server refuses; the client reports the code."""
        cases = [
            ("unknown object, upload", 0x2FFF, 0, True, b"", 4, 0x06020000),
            ("unknown object, expedited download", 0x2FFF, 0, False, b"\x01\x02", None, 0x06020000),
            ("unknown object, segmented download", 0x2FFF, 0, False, bytes(20), None, 0x06020000),
            ("unknown subindex", 0x2105, 9, True, b"", 4, 0x06090011),
            ("read of a write-only object", 0x2104, 0, True, b"", 4, 0x06010001),
            ("write to a read-only object", 0x2103, 0, False, b"\x01\x00", None, 0x06010002),
            ("length does not match", 0x2100, 0, False, b"\x01\x02", None, 0x06070010),
        ]
        for what, index, sub, upload, data, length, code in cases:
            with self.subTest(what):
                self.assertEqual(self.transfer(index, sub, upload, data, length), (RX_ABORTED, code))
        # the channel is free again after an abort
        self.assertEqual(self.transfer(0x2103, 0, True, length=2), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_data(2), struct.pack("<H", 0x0BEE))

    def test_client_configured_over_sdo(self):
        """A master configures the node's client channel in 0x1280 (CiA 301
        7.5.2.34) over SDO; the library uses it."""
        self.node.sdo[CLIENT][1].raw = 0x80000000
        self.node.sdo[CLIENT][2].raw = 0x80000000
        self.node.sdo[CLIENT][3].raw = SERVER_ID
        self.node.sdo[CLIENT][1].raw = 0x600 + SERVER_ID
        self.node.sdo[CLIENT][2].raw = 0x580 + SERVER_ID
        self.server.set_data(0x2100, 0, struct.pack("<I", 0x0A0B0C0D))
        self.assertEqual(self.transfer(0x2100, 0, True, length=4), (FINISHED, 0))
        self.assertEqual(self.peer.sdoc_data(4), struct.pack("<I", 0x0A0B0C0D))

    def test_define_client_tab_shows_in_0x1280(self):
        """CcmSdocDefineClientTab configures the channel and object 0x1280,
        so a master reading the object sees the parameters in use."""
        self.assertEqual(self.node.sdo[CLIENT][1].raw, 0x600 + SERVER_ID)
        self.assertEqual(self.node.sdo[CLIENT][2].raw, 0x580 + SERVER_ID)
        self.assertEqual(self.node.sdo[CLIENT][3].raw, SERVER_ID)

    def test_timeout_without_server(self):
        """No answer within the channel's timeout: the client aborts with
        0x05040000 and tells the (absent) server so."""
        self.peer.sdoc_define(0x23, 0x623, 0x5A3, 200)
        self.assertEqual(self.transfer(0x2100, 0, True, length=4), (TX_ABORTED, 0x05040000))
        aborts = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x623]
        self.assertEqual(aborts[-1], bytes([0x80, 0x00, 0x21, 0x00, 0x00, 0x00, 0x04, 0x05]))


if __name__ == "__main__":
    unittest.main()
