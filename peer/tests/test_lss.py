"""python-canopen's LSS master (CiA 305) against the library's LSS slave:
a node started without node-ID is found by fastscan, given a node-ID and
then answers SDO under it; a configured node is selected by its LSS
address, inquired, identified by ranges, and refuses what it does not
serve (bit timing, store configuration: error 1)."""

import unittest

import canopen
from canopen.lss import (
    CS_INQUIRE_PRODUCT_CODE,
    CS_INQUIRE_REVISION_NUMBER,
    CS_INQUIRE_SERIAL_NUMBER,
    CS_INQUIRE_VENDOR_ID,
    LssError,
)

import copbus
from peertest import EDS_PATH, PEER_NODE_ID, PeerTestCase

K_LSSS_INVALID_NODE_ID = 0x0081
UNCONFIGURED = 0xFF
NEW_NODE_ID = 0x22


class LssTestCase(PeerTestCase):
    CONNECT = False

    def lss_address(self):
        """0x1018 sub 1..4 as the library reads them (peer/objdict.h)."""
        return [int.from_bytes(self.peer.read(0x1018, sub), "little") for sub in (1, 2, 3, 4)]


class Unconfigured(LssTestCase):
    def setUp(self):
        super().setUp()
        self.peer.init(UNCONFIGURED)

    def test_fastscan_then_node_id_then_sdo(self):
        """Fastscan finds the LSS address bit by bit and leaves the slave in
        the configuration state; configure node-ID and switch state global
        to waiting give the node its node-ID (CcmProcessLssInitState then
        succeeds); after CcmConnectToNet it boots up and answers SDO under
        the new node-ID."""
        self.assertEqual(self.peer.process_lss_init(), K_LSSS_INVALID_NODE_ID)
        self.assertEqual(self.peer.connect_code(), K_LSSS_INVALID_NODE_ID)
        lss = self.network.lss
        found, address = lss.fast_scan()
        self.assertTrue(found)
        self.assertEqual(address, self.lss_address())
        self.assertEqual(lss.inquire_node_id(), UNCONFIGURED)
        with self.assertRaises(LssError):
            lss.configure_node_id(0)  # error 1: not 1..127
        lss.configure_node_id(NEW_NODE_ID)
        self.assertEqual(self.peer.process_lss_init(), K_LSSS_INVALID_NODE_ID)
        lss.send_switch_state_global(lss.WAITING_STATE)
        self.wait_until(lambda: self.peer.process_lss_init() == copbus.K_SUCCESSFUL,
                        what="CcmProcessLssInitState to succeed")
        self.assertEqual(self.peer.node_id(), NEW_NODE_ID)

        self.peer.connect()
        self.peer.pump()
        self.assertEqual(self.peer.node_state(), copbus.STATE_PRE_OPERATIONAL)
        node = self.network.add_node(NEW_NODE_ID, EDS_PATH)
        self.assertEqual(node.sdo.upload(0x1018, 1), self.peer.read(0x1018, 1))
        self.assertTrue(any(m.arbitration_id == 0x700 + NEW_NODE_ID for _, m in self.peer.trace))

    def test_a_node_without_node_id_is_silent_but_for_lss(self):
        """NMT start and an SDO request to the would-be node-ID change nothing."""
        self.network.nmt.send_command(0x01)
        self.peer.pump()
        self.assertEqual(self.peer.node_state(), copbus.STATE_INITIALISATION)
        node = self.network.add_node(0x7F, EDS_PATH)
        node.sdo.RESPONSE_TIMEOUT = 0.2
        with self.assertRaises(canopen.SdoCommunicationError):
            node.sdo.upload(0x1018, 1)


class Configured(LssTestCase):
    def test_selective_inquire_and_what_the_slave_refuses(self):
        """Switch state selective with the LSS address answers 0x44; inquire
        returns each part; bit timing and store configuration answer error 1
        (python-canopen raises LssError); the new node-ID waits for reset
        communication."""
        self.peer.connect()
        lss = self.network.lss
        address = self.lss_address()
        self.assertTrue(lss.send_switch_state_selective(*address))
        parts = [lss.inquire_lss_address(cs) for cs in (
            CS_INQUIRE_VENDOR_ID, CS_INQUIRE_PRODUCT_CODE,
            CS_INQUIRE_REVISION_NUMBER, CS_INQUIRE_SERIAL_NUMBER)]
        self.assertEqual(parts, address)
        self.assertEqual(lss.inquire_node_id(), PEER_NODE_ID)
        with self.assertRaises(LssError):
            lss.configure_bit_timing(2)
        with self.assertRaises(LssError):
            lss.store_configuration()
        lss.configure_node_id(NEW_NODE_ID)
        lss.send_switch_state_global(lss.WAITING_STATE)
        self.peer.pump()
        self.assertEqual(self.peer.node_id(), PEER_NODE_ID)
        self.node.nmt.send_command(0x82)  # reset communication
        self.wait_until(lambda: self.peer.node_id() == NEW_NODE_ID, what="the new node-ID")

    def test_identify_remote_slave_by_ranges(self):
        """Identify remote slave answers 0x4F when vendor-ID and product
        code are equal and revision and serial number within the ranges."""
        self.peer.connect()
        lss = self.network.lss
        vendor, product, revision, serial = self.lss_address()
        lss.send_identify_remote_slave(vendor, product, 0, revision, serial, serial + 10)
        self.assertEqual(lss.responses.get(timeout=1.0)[0], 0x4F)
        lss.send_identify_remote_slave(vendor, product, revision + 1, revision + 2, 0, 0xFFFFFFFF)
        with self.assertRaises(Exception):
            lss.responses.get(timeout=0.3)


if __name__ == "__main__":
    unittest.main()
