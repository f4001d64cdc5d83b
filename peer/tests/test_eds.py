"""peer/peer_node.eds against the library: the object dictionary python-
canopen builds from the EDS must be the one the library runs (the tables
objdef.h generated from peer/objdict.h), object by object - existence,
data type, access, PDO mapping, value range - and every value read over
SDO must be the EDS default, decoded by python-canopen."""

import struct
import unittest

from canopen import objectdictionary as od
from canopen.objectdictionary import datatypes

from peertest import PeerTestCase

# tObdSubEntry access bits and storage kinds (cop_types.h)
ACC_READ, ACC_WRITE, ACC_CONST, ACC_PDO, ACC_ARRAY, ACC_RANGE = 0x01, 0x02, 0x04, 0x08, 0x10, 0x20
KIND_ROM = 1

# struct formats of the fixed-size types, as python-canopen decodes them
NATIVE = {
    datatypes.BOOLEAN: "<?",
    datatypes.INTEGER8: "<b",
    datatypes.INTEGER16: "<h",
    datatypes.INTEGER32: "<i",
    datatypes.INTEGER64: "<q",
    datatypes.UNSIGNED8: "<B",
    datatypes.UNSIGNED16: "<H",
    datatypes.UNSIGNED32: "<I",
    datatypes.UNSIGNED64: "<Q",
    datatypes.REAL32: "<f",
    datatypes.REAL64: "<d",
}


def eds_variables(dictionary):
    """Every (index, sub) -> ODVariable of a python-canopen dictionary."""
    out = {}
    for obj in dictionary.values():
        if isinstance(obj, od.ODVariable):
            out[(obj.index, 0)] = obj
        else:
            for var in obj.values():
                out[(var.index, var.subindex)] = var
    return out


# Objects whose EDS default is "$NODEID + base": the library answers the
# base alone (see test_node_id_based_cob_ids, a known deviation).
NODE_ID_COB_IDS = {(0x1014, 0), (0x1200, 1), (0x1200, 2)}


def access_name(access):
    if access & ACC_CONST:
        return "const"
    return {ACC_READ: "ro", ACC_WRITE: "wo", ACC_READ | ACC_WRITE: "rw"}[access & (ACC_READ | ACC_WRITE)]


class EdsMatchesLibrary(PeerTestCase):
    def library_variables(self):
        """Every (index, sub) of the library's tables; array entries expanded."""
        out = {}
        for index, sub, typ, acc, kind, size in self.peer.od_entries():
            if acc & ACC_ARRAY:
                count = self.peer.read(index, 0)[0]
                for s in range(sub, sub + count):
                    out[(index, s)] = (typ, acc & ~ACC_ARRAY, kind, size)
            else:
                out[(index, sub)] = (typ, acc, kind, size)
        return out

    def test_same_objects_types_access(self):
        eds = eds_variables(self.node.object_dictionary)
        lib = self.library_variables()
        self.assertEqual(sorted(eds), sorted(lib), "objects of the EDS and of the library differ")
        for key, var in sorted(eds.items()):
            typ, acc, kind, size = lib[key]
            with self.subTest(object=f"0x{key[0]:04X}/{key[1]}"):
                self.assertEqual(var.data_type, typ, "data type")
                self.assertEqual(var.access_type, access_name(acc), "access")
                self.assertEqual(var.pdo_mappable, bool(acc & ACC_PDO), "PDO mapping")
                if var.data_type in NATIVE:
                    self.assertEqual(struct.calcsize(NATIVE[var.data_type]), size, "size")
                limits = self.peer.od_limits(*key)
                self.assertEqual(limits is not None, bool(acc & ACC_RANGE))
                if limits is not None:
                    fmt = NATIVE[var.data_type]
                    self.assertEqual(struct.unpack(fmt, limits[0])[0], var.min, "LowLimit")
                    self.assertEqual(struct.unpack(fmt, limits[1])[0], var.max, "HighLimit")
                else:
                    self.assertIsNone(var.min)
                    self.assertIsNone(var.max)

    def test_values_over_sdo_are_eds_defaults(self):
        """Each readable object, uploaded by python-canopen and decoded with
        the EDS type, equals the EDS default (and the library's own view
        through CcmReadObject)."""
        version = self.peer.stack_version()
        major, minor, release = version & 0xFF, (version >> 8) & 0xFF, version >> 16
        expected_special = {
            (0x100A, 0): f"V{major}.{minor} r{release}",
            (0x1018, 3): (major << 16) | minor,
            (0x2002, 0): bytes(300),
        }
        for key, var in sorted(eds_variables(self.node.object_dictionary).items()):
            if not var.readable or key in NODE_ID_COB_IDS:
                continue
            with self.subTest(object=f"0x{key[0]:04X}/{key[1]}"):
                sdo = self.node.sdo[key[0]] if key[1] == 0 and isinstance(
                    self.node.object_dictionary[key[0]], od.ODVariable
                ) else self.node.sdo[key[0]][key[1]]
                value = sdo.raw
                expected = expected_special.get(key, var.default)
                self.assertIsNotNone(expected, "EDS without DefaultValue")
                self.assertEqual(value, expected)
                local = self.peer.read(*key)
                if var.data_type in NATIVE:
                    self.assertEqual(struct.unpack(NATIVE[var.data_type], local)[0], value)
                elif var.data_type == datatypes.VISIBLE_STRING:
                    self.assertEqual(local.decode("ascii"), value)
                else:
                    self.assertEqual(local, value)

    def test_node_id_based_cob_ids(self):
        """objdict.h declares 0x1200 and 0x1014 with the base COB-ID (0x600,
        0x580, 0x80) because the node-ID is only known at run time; the
        objects must show the COB-ID in use (CiA 301 7.5.2.33; the EDS says
        $NODEID+0x600), so a master reads base + node-ID."""
        eds = eds_variables(self.node.object_dictionary)
        for index, sub in sorted(NODE_ID_COB_IDS):
            with self.subTest(object=f"0x{index:04X}/{sub}"):
                self.assertEqual(self.node.sdo.upload(index, sub), struct.pack("<I", eds[(index, sub)].default))

if __name__ == "__main__":
    unittest.main()
