"""python-canopen as NMT master of the library node: boot-up, heartbeat
producer (0x1017) and every NMT command (CiA 301 7.2.8.3.1), seen both
from the bus (heartbeat state) and from the library (CcmObdGetNodeState,
NMT callback)."""

import threading
import time
import unittest

import canopen

import copbus
from peertest import PEER_NODE_ID, PeerTestCase

# NMT callback events (cop_types.h)
EV_ENTER_PRE_OPERATIONAL = 0x10
EV_ENTER_OPERATIONAL = 0x20
EV_ENTER_STOPPED = 0x30
EV_RESET_NODE = 0x02
EV_RESET_COMMUNICATION = 0x04


class HeartbeatLog:
    """Every heartbeat state python-canopen's NmtMaster decodes."""

    def __init__(self, node):
        self.states = []
        self.cond = threading.Condition()
        node.nmt.add_heartbeat_callback(self._on)

    def _on(self, state):
        with self.cond:
            self.states.append(state)
            self.cond.notify_all()

    def wait_for(self, state, timeout=2.0):
        end = time.monotonic() + timeout
        with self.cond:
            while state not in self.states:
                left = end - time.monotonic()
                if left <= 0:
                    return False
                self.cond.wait(left)
            return True

    def clear(self):
        with self.cond:
            self.states.clear()


class BootUp(PeerTestCase):
    CONNECT = False

    def test_bootup_seen_by_python_canopen(self):
        """CcmConnectToNet sends the boot-up message (0x705, [00]) that
        NmtMaster.wait_for_bootup waits for; the node is then PRE-OPERATIONAL."""
        self.assertEqual(self.peer.node_state(), copbus.STATE_INITIALISATION)
        timer = threading.Timer(0.1, self.peer.connect)
        timer.start()
        try:
            self.node.nmt.wait_for_bootup(timeout=3)
        finally:
            timer.join()
        self.assertEqual(self.node.nmt.state, "PRE-OPERATIONAL")
        self.assertEqual(self.peer.node_state(), copbus.STATE_PRE_OPERATIONAL)
        nmt = [e.code for e in self.events(copbus.EV_NMT)]
        self.assertEqual(nmt[-1], EV_ENTER_PRE_OPERATIONAL)
        boot = [m for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x700 + PEER_NODE_ID]
        self.assertEqual([bytes(m.data) for m in boot], [b"\x00"])


class Nmt(PeerTestCase):
    def setUp(self):
        super().setUp()
        self.hb = HeartbeatLog(self.node)
        # Producer heartbeat time written by the master, as a configurator does.
        self.node.sdo[0x1017].raw = 20
        self.assertTrue(self.hb.wait_for(0x7F), "no heartbeat after 0x1017 = 20 ms")

    def expect_state(self, command, heartbeat, local, event):
        self.hb.clear()
        self.events(copbus.EV_NMT)
        self.node.nmt.state = command
        self.assertTrue(self.hb.wait_for(heartbeat), f"no heartbeat 0x{heartbeat:02X} after {command}")
        self.assertEqual(self.node.nmt.wait_for_heartbeat(timeout=1), canopen.nmt.NMT_STATES[heartbeat])
        self.assertEqual(self.peer.node_state(), local)
        self.assertIn(event, [e.code for e in self.events(copbus.EV_NMT)])

    def test_heartbeat_reports_pre_operational(self):
        self.assertEqual(self.node.nmt.wait_for_heartbeat(timeout=1), "PRE-OPERATIONAL")

    def test_heartbeat_period_follows_0x1017(self):
        """20 ms producer time: about 50 heartbeats per second (the
        simulated clock follows the wall clock; the window is generous
        because the machine is shared)."""
        self.hb.clear()
        time.sleep(1.0)
        with self.hb.cond:
            n = len(self.hb.states)
        self.assertGreaterEqual(n, 25)
        self.assertLessEqual(n, 55)
        self.node.sdo[0x1017].raw = 0
        time.sleep(0.05)
        self.hb.clear()
        time.sleep(0.2)
        self.assertEqual(self.hb.states, [], "heartbeats after 0x1017 = 0")

    def test_start_stop_pre_operational(self):
        self.expect_state("OPERATIONAL", 0x05, copbus.STATE_OPERATIONAL, EV_ENTER_OPERATIONAL)
        self.expect_state("STOPPED", 0x04, copbus.STATE_STOPPED, EV_ENTER_STOPPED)
        self.expect_state("PRE-OPERATIONAL", 0x7F, copbus.STATE_PRE_OPERATIONAL, EV_ENTER_PRE_OPERATIONAL)
        self.expect_state("OPERATIONAL", 0x05, copbus.STATE_OPERATIONAL, EV_ENTER_OPERATIONAL)
        self.expect_state("PRE-OPERATIONAL", 0x7F, copbus.STATE_PRE_OPERATIONAL, EV_ENTER_PRE_OPERATIONAL)
        self.expect_state("STOPPED", 0x04, copbus.STATE_STOPPED, EV_ENTER_STOPPED)
        self.expect_state("OPERATIONAL", 0x05, copbus.STATE_OPERATIONAL, EV_ENTER_OPERATIONAL)

    def test_stopped_node_does_not_answer_sdo(self):
        """CiA 301: SDO is not available in STOPPED."""
        self.expect_state("STOPPED", 0x04, copbus.STATE_STOPPED, EV_ENTER_STOPPED)
        with self.assertRaises(canopen.SdoCommunicationError):
            self.node.sdo[0x1000].raw
        self.expect_state("PRE-OPERATIONAL", 0x7F, copbus.STATE_PRE_OPERATIONAL, EV_ENTER_PRE_OPERATIONAL)
        self.assertEqual(self.node.sdo[0x1000].raw, 0x00030191)

    def test_broadcast_and_other_node(self):
        """Node-ID 0 addresses every node; a command for another node is ignored."""
        self.hb.clear()
        self.network.send_message(0x000, [0x01, 0x00])  # start all nodes
        self.assertTrue(self.hb.wait_for(0x05))
        self.assertEqual(self.peer.node_state(), copbus.STATE_OPERATIONAL)
        self.network.send_message(0x000, [0x02, PEER_NODE_ID + 1])  # stop node 6
        time.sleep(0.1)
        self.assertEqual(self.peer.node_state(), copbus.STATE_OPERATIONAL)
        self.hb.clear()
        self.assertTrue(self.hb.wait_for(0x05))
        self.assertNotIn(0x04, self.hb.states)

    def test_node_guarding(self):
        """Without heartbeat (0x1017 = 0) the node answers python-canopen's
        guarding requests (remote frames on 0x705): one answer per request,
        state in bits 0-6, toggle bit alternating from 0 (CiA 301
        7.2.8.3.2.1)."""
        self.expect_state("OPERATIONAL", 0x05, copbus.STATE_OPERATIONAL, EV_ENTER_OPERATIONAL)
        self.node.sdo[0x1017].raw = 0
        time.sleep(0.05)
        self.peer.trace.clear()
        self.hb.clear()
        self.node.nmt.start_node_guarding(0.05)
        try:
            time.sleep(0.5)
        finally:
            self.node.nmt.stop_node_guarding()
        time.sleep(0.05)
        requests = [m for who, m in self.peer.trace if who == "python" and m.arbitration_id == 0x705]
        answers = [m.data[0] for who, m in self.peer.trace if who == "node" and m.arbitration_id == 0x705]
        self.assertTrue(all(m.is_remote_frame for m in requests))
        self.assertGreaterEqual(len(requests), 4)
        self.assertEqual(len(answers), len(requests))
        self.assertEqual([a & 0x7F for a in answers], [0x05] * len(answers))
        self.assertEqual([a >> 7 for a in answers], [i % 2 for i in range(len(answers))])
        self.assertEqual(self.node.nmt.state, "OPERATIONAL")

    def test_reset_communication(self):
        """Reset communication: boot-up, communication objects (0x1000..0x1FFF)
        back to their defaults, application objects kept."""
        self.node.sdo[0x2000][6].raw = 0x11
        self.expect_state("OPERATIONAL", 0x05, copbus.STATE_OPERATIONAL, EV_ENTER_OPERATIONAL)
        self.hb.clear()
        self.events(copbus.EV_NMT)
        self.node.nmt.state = "RESET COMMUNICATION"
        self.assertTrue(self.hb.wait_for(0x00), "no boot-up after reset communication")
        self.assertEqual(self.peer.node_state(), copbus.STATE_PRE_OPERATIONAL)
        events = [e.code for e in self.events(copbus.EV_NMT)]
        self.assertIn(EV_RESET_COMMUNICATION, events)
        self.assertNotIn(EV_RESET_NODE, events)
        self.assertEqual(events[-1], EV_ENTER_PRE_OPERATIONAL)
        self.assertEqual(self.node.sdo[0x1017].raw, 0)
        self.assertEqual(self.node.sdo[0x2000][6].raw, 0x11)

    def test_reset_node(self):
        """Reset node: boot-up, every object back to its default."""
        self.node.sdo[0x2000][6].raw = 0x11
        self.node.sdo[0x2003].raw = 0x01020304
        self.hb.clear()
        self.events(copbus.EV_NMT)
        self.node.nmt.state = "RESET"
        self.assertTrue(self.hb.wait_for(0x00), "no boot-up after reset node")
        self.assertEqual(self.peer.node_state(), copbus.STATE_PRE_OPERATIONAL)
        events = [e.code for e in self.events(copbus.EV_NMT)]
        self.assertIn(EV_RESET_NODE, events)
        self.assertEqual(events[-1], EV_ENTER_PRE_OPERATIONAL)
        self.assertEqual(self.node.sdo[0x1017].raw, 0)
        self.assertEqual(self.node.sdo[0x2000][6].raw, 0xA8)
        self.assertEqual(self.node.sdo[0x2003].raw, 0x5EED0001)


if __name__ == "__main__":
    unittest.main()
