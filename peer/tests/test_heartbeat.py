"""python-canopen as heartbeat producer (a LocalNode, node-ID 0x22) and NMT
slave, supervised by the library's heartbeat consumer (0x1016,
CcmInitHbcEx callback, CcmHbcGetNodeState) and commanded by the library's
NMT master (CcmSendNmtCommand)."""

import time
import unittest

from canopen import objectdictionary as od
from canopen.objectdictionary import datatypes

import copbus
from peertest import PeerTestCase

PRODUCER_ID = 0x22
PRODUCER_MS = 50
CONSUMER_MS = 250

# tNmtErrCtrlEvent (cop_types.h)
HBC_CONNECTED = 0x40
HBC_CONNECTION_LOST = 0x41
HBC_NODE_STATE_CHANGED = 0x42
NMTM_BOOTUP_RECEIVED = 0x20

# tNmtCommand (cop_types.h)
CMD_START = 0x0001
CMD_STOP = 0x0002
CMD_PRE_OPERATIONAL = 0x0080


def producer_dictionary():
    d = od.ObjectDictionary()
    v = od.ODVariable("Producer heartbeat time", 0x1017, 0)
    v.data_type = datatypes.UNSIGNED16
    v.access_type = "rw"
    v.default = PRODUCER_MS
    d.add_object(v)
    return d


class HeartbeatConsumer(PeerTestCase):
    def setUp(self):
        super().setUp()
        self.producer = self.network.create_node(PRODUCER_ID, producer_dictionary())
        self.addCleanup(self.producer.nmt.stop_heartbeat)
        self.peer.take_events()

    def hbc_events(self):
        return [(e.node, e.code) for e in self.peer.take_events(copbus.EV_HBC)]

    def wait_hbc(self, code, timeout=2.0):
        seen = []

        def got():
            seen.extend(self.hbc_events())
            return (PRODUCER_ID, code) in seen

        self.wait_until(got, timeout=timeout, what=f"heartbeat consumer event 0x{code:02X}")
        return seen

    def start_producer(self):
        """Boot-up, then PRE-OPERATIONAL: python-canopen's NmtSlave starts
        its heartbeat from its own 0x1017 on that transition."""
        self.producer.nmt.state = "INITIALISING"
        self.producer.nmt.state = "PRE-OPERATIONAL"

    def supervise_and_check(self):
        # The boot-up message (state 0) is the first heartbeat: connected;
        # the heartbeats with 0x7F that follow are a change of state.
        self.start_producer()
        seen = self.wait_hbc(HBC_NODE_STATE_CHANGED)
        self.assertEqual(seen, [(PRODUCER_ID, HBC_CONNECTED), (PRODUCER_ID, HBC_NODE_STATE_CHANGED)])
        self.wait_until(lambda: self.peer.hbc_node_state(PRODUCER_ID) == 0x7F, what="state 0x7F")

        self.producer.nmt.state = "OPERATIONAL"
        self.wait_hbc(HBC_NODE_STATE_CHANGED)
        self.wait_until(lambda: self.peer.hbc_node_state(PRODUCER_ID) == 0x05, what="state 0x05")

        # the producer falls silent: lost once, not again
        self.producer.nmt.stop_heartbeat()
        t0 = time.monotonic()
        self.wait_hbc(HBC_CONNECTION_LOST, timeout=3.0)
        self.assertGreaterEqual(time.monotonic() - t0, (CONSUMER_MS - PRODUCER_MS) / 1000.0 * 0.9)
        time.sleep(3 * CONSUMER_MS / 1000.0)
        self.assertEqual(self.hbc_events(), [])
        # a lost node reads "disconnected" (0x01), not its last state
        self.assertEqual(self.peer.hbc_node_state(PRODUCER_ID), 0x01)

        # back again: connected, with the state its heartbeat carries
        self.producer.nmt.start_heartbeat(PRODUCER_MS)
        self.wait_hbc(HBC_CONNECTED)
        self.wait_until(lambda: self.peer.hbc_node_state(PRODUCER_ID) == 0x05, what="state 0x05 again")

    def test_supervision_defined_by_the_application(self):
        """CcmHbcDefineProducerTab writes 0x1016 (checked over SDO by
        python-canopen: node-ID << 16 | time)."""
        self.peer.hbc_define(PRODUCER_ID, CONSUMER_MS, 1)
        self.assertEqual(self.node.sdo[0x1016][1].raw, (PRODUCER_ID << 16) | CONSUMER_MS)
        self.supervise_and_check()

    def test_supervision_configured_over_sdo(self):
        """A master writes 0x1016 sub 2; the consumer follows the object."""
        self.node.sdo[0x1016][2].raw = (PRODUCER_ID << 16) | CONSUMER_MS
        self.supervise_and_check()

    def test_no_event_for_unsupervised_node(self):
        self.start_producer()
        time.sleep(0.3)
        self.assertEqual(self.hbc_events(), [])
        self.assertIsNone(self.peer.hbc_node_state(PRODUCER_ID))


class NmtMaster(PeerTestCase):
    """The library commands python-canopen's NmtSlave; the slave's heartbeat
    shows the new state to the library's consumer."""

    def setUp(self):
        super().setUp()
        self.producer = self.network.create_node(PRODUCER_ID, producer_dictionary())
        self.addCleanup(self.producer.nmt.stop_heartbeat)
        self.peer.hbc_define(PRODUCER_ID, CONSUMER_MS, 1)
        self.peer.take_events()

    def test_bootup_reported(self):
        self.producer.nmt.state = "INITIALISING"  # python-canopen sends 0x722 [00]
        self.wait_until(
            lambda: any(
                e.node == PRODUCER_ID and e.code == NMTM_BOOTUP_RECEIVED
                for e in self.peer.take_events(copbus.EV_NMTM)
            ),
            what="boot-up event",
        )

    def test_commands_reach_the_slave(self):
        self.producer.nmt.state = "INITIALISING"
        self.producer.nmt.state = "PRE-OPERATIONAL"
        self.wait_until(lambda: self.peer.hbc_node_state(PRODUCER_ID) == 0x7F, what="state 0x7F")
        for command, name, state in (
            (CMD_START, "OPERATIONAL", 0x05),
            (CMD_STOP, "STOPPED", 0x04),
            (CMD_PRE_OPERATIONAL, "PRE-OPERATIONAL", 0x7F),
        ):
            with self.subTest(command=name):
                self.peer.nmtm_command(PRODUCER_ID, command)
                self.wait_until(lambda: self.producer.nmt.state == name, what=f"slave {name}")
                self.wait_until(
                    lambda: self.peer.hbc_node_state(PRODUCER_ID) == state, what=f"heartbeat 0x{state:02X}"
                )
                # addressed to node 0x22 only: the library node stays PRE-OPERATIONAL
                self.assertEqual(self.peer.node_state(), copbus.STATE_PRE_OPERATIONAL)
        frames = [bytes(m.data) for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x000]
        self.assertEqual(frames, [bytes([0x01, 0x22]), bytes([0x02, 0x22]), bytes([0x80, 0x22])])

    def test_broadcast_start(self):
        """Node-ID 0: every node, the master's own node included."""
        self.peer.nmtm_command(0, CMD_START)
        self.wait_until(lambda: self.producer.nmt.state == "OPERATIONAL", what="slave OPERATIONAL")
        self.assertEqual(self.peer.node_state(), copbus.STATE_OPERATIONAL)


if __name__ == "__main__":
    unittest.main()
