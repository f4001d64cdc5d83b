"""Common set-up of the interoperability tests.

Every test gets a fresh library node (node-ID 5, INITIALISATION, clock at
0) on a fresh bus, a python-canopen ``Network`` on that bus and a
``RemoteNode`` for the library node described by peer/peer_node.eds. When
a test fails, the frames of its scenario are printed in candump form.
"""

import logging
import os
import sys
import time
import unittest

import canopen

from copbus import CopBus, PeerLibrary

# python-canopen logs the errors these tests provoke on purpose (aborts,
# timeouts); shown only with COP_PEER_TRACE.
if not os.environ.get("COP_PEER_TRACE"):
    logging.getLogger("canopen").setLevel(logging.CRITICAL)

PEER_NODE_ID = 5
EDS_PATH = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "peer_node.eds")

# Loaded once: the shared library holds one stack instance per process.
_LIBRARY = None


def library():
    global _LIBRARY
    if _LIBRARY is None:
        _LIBRARY = PeerLibrary()
    return _LIBRARY


class PeerTestCase(unittest.TestCase):
    """A library node and python-canopen on one simulated bus."""

    CONNECT = True  # CcmConnectToNet in setUp (PRE-OPERATIONAL)

    def setUp(self):
        self.peer = library()
        self.peer.init(PEER_NODE_ID)
        self.bus = CopBus(self.peer)
        self.network = canopen.Network(self.bus)
        self.network.connect()
        # a cleanup, not tearDown: it also runs when a subclass's setUp fails
        self.addCleanup(self._close)
        self.node = self.network.add_node(PEER_NODE_ID, EDS_PATH)
        if self.CONNECT:
            self.peer.connect()

    def _close(self):
        if self._failed() or os.environ.get("COP_PEER_TRACE"):
            sys.stderr.write(f"\n--- frames of {self.id()} ---\n{self.peer.candump()}\n")
        self.network.disconnect()
        self.peer.shutdown()

    def _failed(self):
        result = getattr(self._outcome, "result", None)
        if result is None:
            return False
        return any(t is self for t, _ in list(result.failures) + list(result.errors))

    def wait_until(self, predicate, timeout=2.0, what="condition"):
        """Polls predicate (the bus keeps running meanwhile) until it is true."""
        end = time.monotonic() + timeout
        while True:
            value = predicate()
            if value:
                return value
            if time.monotonic() > end:
                self.fail(f"timeout waiting for {what}")
            time.sleep(0.005)

    def events(self, kind):
        """Events of one kind the library reported since the last call."""
        return self.peer.take_events(kind)
