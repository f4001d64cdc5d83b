"""Store / restore (CiA 301 7.5.2.13 / 7.5.2.14) driven by python-canopen:
``RemoteNode.store()`` writes "save" to 0x1010 sub 1 and ``restore()``
"load" to 0x1011 sub 1 over SDO. The library node uses the simulated
memory of examples_c/sim/store_sim.h; a restart is a new CcmInitCANopen
(RAM variables back to their defaults, CcmInitStore in the NMT callback
as the SYS TEC slave calls it) with the memory kept."""

import time

import canopen

import copbus
from peertest import PeerTestCase
from test_srdo import COB1, COB2, SRDO, TX_MAPPING, SrdoTestCase


class StoreMixin:
    def use_storage(self):
        self.addCleanup(self.peer.store_use, False)
        self.peer.store_use(True)
        self.restart()
        self.assertEqual(self.peer.init_store_result(), copbus.K_SUCCESSFUL)

    def restart(self):
        self.peer.init(5)
        self.peer.connect()
        self.wait_until(
            lambda: self.peer.node_state() == copbus.STATE_PRE_OPERATIONAL, what="PRE-OPERATIONAL"
        )


class Store(StoreMixin, PeerTestCase):
    def test_without_a_driver_save_is_refused(self):
        self.assertEqual(self.node.sdo[0x1010][1].raw, 0)
        with self.assertRaises(canopen.SdoAbortedError) as caught:
            self.node.store()
        self.assertEqual(caught.exception.code, 0x08000020)

    def test_values_back_after_a_restart_and_gone_after_restore(self):
        self.use_storage()
        self.assertEqual(self.node.sdo[0x1010][1].raw, 1)  # saves on command
        self.node.sdo[0x1017].raw = 500
        self.node.store()
        self.node.sdo[0x1017].raw = 100
        self.restart()
        self.assertEqual(self.peer.init_store_result(), copbus.K_SUCCESSFUL)
        self.assertEqual(self.node.sdo[0x1017].raw, 500)
        self.node.restore()
        self.restart()
        self.assertEqual(self.node.sdo[0x1017].raw, 0)


class StoredSrdo(StoreMixin, SrdoTestCase):
    def test_configured_over_sdo_stored_restarted_running(self):
        self.use_storage()
        crc = self.configure(1, 50, 20, COB1, COB2, TX_MAPPING)
        self.node.sdo[0x13FE].raw = 0xA5
        self.node.store()
        self.restart()
        self.assertEqual(self.node.sdo[0x13FE].raw, 0xA5)
        self.assertEqual(self.node.sdo[0x13FF][1].raw, crc)
        self.assertEqual(self.node.sdo[SRDO][2].raw, 50)
        self.assertEqual(self.peer.check_srdo_config(), (copbus.K_SUCCESSFUL, 0))
        self.start()
        time.sleep(0.01)
        self.taken_frames()
        self.assertEqual(self.peer.send_srdo(SRDO), copbus.K_SUCCESSFUL)
        frames = self.wait_until(lambda: len(self.frames) >= 2 and self.taken_frames(), what="SRDO pair")
        self.assertEqual([f[0] for f in frames], [COB1, COB2])
        self.assertEqual(bytes(b ^ 0xFF for b in frames[0][1]), frames[1][1])
