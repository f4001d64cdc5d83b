"""The dynamic object dictionary (DynBuildOd, seed manual L-1087d) as
python-canopen sees it: the node builds its dynamic OD from the container
dcf2bin made of peer/peer_dynod.dcf, python-canopen loads the same DCF as
its object dictionary and reads every object of it over SDO. The network
variables live in the process image the harness hands to DynBuildOd; the
reconfigured TPDO is read back by python-canopen's PDO support and received
in OPERATIONAL. After DynDestroyOd the new objects are gone (abort
0x06020000) and the TPDO has its peer/objdict.h defaults again."""

import os
import struct
import sys
import unittest

import canopen
from canopen import objectdictionary as od
from canopen.objectdictionary import datatypes

import copbus
from peertest import PEER_NODE_ID, PeerTestCase

DCF_PATH = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "peer_dynod.dcf")

ABORT_OBJECT_NOT_EXIST = 0x06020000
ABORT_WRITE_READ_ONLY = 0x06010002
K_NO_FREE_INSTANCE = 0x0003

# Network variables of the DCF: (index, sub) -> (offset in the output area,
# struct format), by the CiA 302/405 rule (seed chapter 6): element
# (index - range start) * 254 + sub - 1 of the array of its type.
NATIVE = "<" if sys.byteorder == "little" else ">"
NETWORK_VARIABLES = {
    (0xA4C0, 1): (0, "B"),
    (0xA4C0, 2): (1, "B"),
    (0xA580, 2): (2, "H"),
    (0xA580, 3): (4, "H"),
}


def variables(dictionary):
    """Every (index, sub) -> ODVariable of a python-canopen dictionary."""
    out = {}
    for obj in dictionary.values():
        if isinstance(obj, od.ODVariable):
            out[(obj.index, 0)] = obj
        else:
            for var in obj.values():
                out[(var.index, var.subindex)] = var
    return out


def configured(var):
    """The value the DCF configures: ParameterValue, else DefaultValue
    (dcf2bin's rule)."""
    return var.value if var.value is not None else var.default


def wire(var, value):
    """value as the bytes of an SDO upload of var."""
    if var.data_type == datatypes.VISIBLE_STRING:
        return value.encode("ascii")
    if var.data_type in (datatypes.DOMAIN, datatypes.OCTET_STRING):
        return value
    return var.encode_raw(value)


class DynamicOd(PeerTestCase):
    def setUp(self):
        super().setUp()
        self.eds = self.node.object_dictionary  # peer/peer_node.eds: the static part
        self.dcf = canopen.import_od(DCF_PATH, PEER_NODE_ID)
        # python-canopen's view of the node is now the DCF
        del self.network[PEER_NODE_ID]
        self.dyn = self.network.add_node(PEER_NODE_ID, self.dcf)

    def build(self):
        self.assertGreater(self.peer.dyn_container_size(), 40, "container header and segments")
        return self.peer.dyn_build()

    def upload_abort(self, index, sub):
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.dyn.sdo.upload(index, sub)
        return cm.exception.code

    def test_every_object_of_the_dcf_over_sdo(self):
        """Each object of the DCF, uploaded by python-canopen, has the bytes
        of its configured value and decodes to it with the DCF's type (new
        objects get a type of the same size: attribute NUMERIC is an
        UNSIGNEDn, seed chapter 2.1.4)."""
        self.build()
        dcf = variables(self.dcf)
        self.assertGreater(len(dcf), 25)
        for (index, sub), var in sorted(dcf.items()):
            with self.subTest(object=f"0x{index:04X}/{sub}"):
                expected = configured(var)
                self.assertIsNotNone(expected, "DCF without value")
                data = self.dyn.sdo.upload(index, sub)
                self.assertEqual(data, wire(var, expected))
                self.assertEqual(var.decode_raw(data), expected)
        # new read-only object: no write
        with self.assertRaises(canopen.SdoAbortedError) as cm:
            self.dyn.sdo.download(0x2103, 0, struct.pack("<H", 1))
        self.assertEqual(cm.exception.code, ABORT_WRITE_READ_ONLY)
        # new writable objects take values over SDO like static ones
        self.dyn.sdo[0x2100][3].raw = 4321
        self.assertEqual(self.dyn.sdo[0x2100][3].raw, 4321)
        self.dyn.sdo[0x2101].raw = "written"
        self.assertEqual(self.dyn.sdo[0x2101].raw, "written")
        self.assertEqual(self.peer.read(0x2100, 3), struct.pack("<H", 4321))

    def test_network_variables_in_the_process_image(self):
        """0xA4C0 and 0xA580 are outputs: the output area starts at 0 (no
        inputs) and is 6 bytes long; their values are the process image's
        bytes in the CPU's byte order, for SDO and the application alike."""
        size, in_offset, in_size, out_offset, out_size = self.build()
        self.assertEqual((in_offset, in_size), (0, 0))
        self.assertEqual((out_offset, out_size), (0, 6))
        self.assertGreaterEqual(size, 6)
        self.assertLessEqual(size, copbus.PeerLibrary.PROCESS_IMAGE_SIZE)
        image = self.peer.process_image()
        dcf = variables(self.dcf)

        def in_image(key):
            offset, fmt = NETWORK_VARIABLES[key]
            at = out_offset + offset
            with self.peer.lock:
                return struct.unpack(NATIVE + fmt, bytes(image[at : at + struct.calcsize(fmt)]))[0]

        for key in NETWORK_VARIABLES:
            with self.subTest(object=f"0x{key[0]:04X}/{key[1]}"):
                self.assertEqual(in_image(key), configured(dcf[key]))
        # SDO download -> process image
        self.dyn.sdo[0xA4C0][1].raw = 0x77
        self.dyn.sdo[0xA580][3].raw = 0xCAFE
        self.assertEqual(in_image((0xA4C0, 1)), 0x77)
        self.assertEqual(in_image((0xA580, 3)), 0xCAFE)
        # process image (the application) -> SDO upload
        offset, fmt = NETWORK_VARIABLES[(0xA580, 2)]
        with self.peer.lock:
            for i, b in enumerate(struct.pack(NATIVE + fmt, 0x4321)):
                image[out_offset + offset + i] = b
        self.assertEqual(self.dyn.sdo[0xA580][2].raw, 0x4321)

    def test_reconfigured_tpdo(self):
        """TPDO 1 of the static dictionary, reconfigured by the container:
        python-canopen reads its parameters over SDO (PdoMap.read), then
        receives it in OPERATIONAL (event timer 20 ms) and decodes 0xA4C0/1,
        0xA580/2 and the BOOLEAN 0x2100/1 mapped as one bit."""
        self.build()
        tpdo = self.dyn.tpdo[1]
        tpdo.read()
        self.assertEqual(tpdo.cob_id, 0x180 + PEER_NODE_ID)
        self.assertTrue(tpdo.enabled)
        self.assertEqual(tpdo.trans_type, 254)
        self.assertEqual(tpdo.event_timer, 20)
        self.assertEqual(
            [(v.index, v.subindex, v.length) for v in tpdo.map],
            [(0xA4C0, 1, 8), (0xA580, 2, 16), (0x2100, 1, 1)],
        )
        self.dyn.nmt.state = "OPERATIONAL"
        self.wait_until(lambda: self.peer.node_state() == copbus.STATE_OPERATIONAL, what="OPERATIONAL")
        self.assertIsNotNone(tpdo.wait_for_reception(timeout=2.0), "no TPDO")
        self.assertEqual(bytes(tpdo.data), bytes([0x5A, 0x34, 0x12, 0x01]))
        self.assertEqual([v.raw for v in tpdo.map], [0x5A, 0x1234, True])
        # a new value reaches the next transmission
        self.dyn.sdo[0x2100][1].raw = False
        self.dyn.sdo[0xA4C0][1].raw = 0x01

        def fresh():
            tpdo.wait_for_reception(timeout=0.5)
            return [v.raw for v in tpdo.map] == [0x01, 0x1234, False]

        self.wait_until(fresh, what="TPDO with the new values")

    def test_destroy_removes_the_new_objects(self):
        """DynDestroyOd (seed manual 5.2): every object the container
        created answers 0x06020000; the TPDO it reconfigured has the
        defaults of peer/objdict.h again (invalid, unmapped); a static
        object it wrote keeps the container's value. A second build needs
        the destroy first (kCopNoFreeInstance) and then works again."""
        self.build()
        with self.assertRaises(copbus.CopError) as cm:
            self.peer.dyn_build()
        self.assertEqual(cm.exception.code, K_NO_FREE_INSTANCE)
        self.peer.dyn_destroy()
        static = variables(self.eds)
        new = [key for key in variables(self.dcf) if key not in static]
        self.assertIn((0xA4C0, 1), new)
        self.assertIn((0x2100, 0), new)
        for index, sub in sorted(new):
            with self.subTest(object=f"0x{index:04X}/{sub}"):
                self.assertEqual(self.upload_abort(index, sub), ABORT_OBJECT_NOT_EXIST)
        for key in [(0x1800, 1), (0x1800, 2), (0x1800, 5), (0x1A00, 0), (0x1A00, 1), (0x1A00, 3)]:
            with self.subTest(object=f"0x{key[0]:04X}/{key[1]}"):
                var = static[key]
                self.assertEqual(self.dyn.sdo.upload(*key), var.encode_raw(var.default))
        self.assertEqual(self.dyn.sdo[0x2020][1].raw, 500)
        # the pool is free again
        self.build()
        self.assertEqual(self.dyn.sdo[0x2100][4].raw, 0xDEADBEEF)


if __name__ == "__main__":
    unittest.main()
