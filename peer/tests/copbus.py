"""The library as a node on a python-can bus.

``PeerLibrary`` loads ``libcop_peer.so`` (peer/peer_harness.h) with ctypes
and serialises every call with one lock: python-can's Notifier thread
receives while the test thread sends and inspects. ``CopBus`` is the
``can.BusABC`` python-canopen talks to: a frame it sends is put on the
simulated bus (``PeerInject``) and processed at once, and every frame the
node sends (``PeerTakeSent``) is handed out by ``recv``.

Time: the simulation's clock (ticks of 100 us) only moves when told to.
python-canopen waits in real time (SDO response timeout, heartbeat waits),
so before every library call the clock is moved forward to the wall-clock
time elapsed since ``init`` (plus whatever ``advance_ms`` added). ``recv``
polls the node every millisecond, so heartbeats and timeouts of the
library happen in real time too.
"""

import collections
import ctypes
import os
import threading
import time

import can

TICKS_PER_SECOND = 10_000  # one tick = 100 us (tTime)

# tCopKernel values the tests use (include/cop_types.h).
K_SUCCESSFUL = 0x0000
K_SRDO_CFG_CRC_ERROR = 0x0104
K_SRDO_NMT_ERROR = 0x0105
K_SRDO_INVALID_CFG = 0x0106
K_SRDO_NOT_IN_ORDER = 0x010B
K_SRDO_SCT_TIMEOUT = 0x010C
K_SRDO_DATA_ERROR = 0x0111

# Event kinds of PeerTakeEvent (peer_harness.h).
EV_NMT = 1
EV_HBC = 2
EV_NMTM = 3
EV_SRDO = 4
EV_SRDO_ERROR = 5
EV_GFC = 6
EV_SDOC = 7

# NMT states (CcmObdGetNodeState, CiA 301 heartbeat values).
STATE_INITIALISATION = 0x00
STATE_STOPPED = 0x04
STATE_OPERATIONAL = 0x05
STATE_PRE_OPERATIONAL = 0x7F

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_LIBRARY = os.path.join(ROOT, "build", "peer", "peer", "libcop_peer.so")


class CopError(Exception):
    """A harness call returned a tCopKernel other than kCopSuccessful."""

    def __init__(self, what, code):
        super().__init__(f"{what} returned tCopKernel 0x{code:04X}")
        self.code = code


class Event(collections.namedtuple("Event", "kind node index code")):
    """One application callback the library made (PeerTakeEvent)."""


class PeerLibrary:
    """ctypes view of libcop_peer.so: one CANopen node on a simulated bus."""

    def __init__(self, path=None):
        path = path or os.environ.get("COP_PEER_LIB", DEFAULT_LIBRARY)
        self.lib = ctypes.CDLL(path)
        self.lock = threading.RLock()
        self.sent = collections.deque()  # frames of the node, not yet received
        self.events = []  # every callback since init
        self.trace = []  # (direction, can.Message) of every frame, for failure reports
        self._t0 = time.monotonic()
        self._ticks = 0
        self._offset_ticks = 0
        self._declare()

    def _declare(self):
        c = ctypes
        u8p, u16p, u32p = (c.POINTER(c.c_uint8), c.POINTER(c.c_uint16), c.POINTER(c.c_uint32))
        sig = {
            "PeerInit": (c.c_uint32, [c.c_uint8]),
            "PeerConnect": (c.c_uint32, []),
            "PeerShutdown": (c.c_uint32, []),
            "PeerProcess": (c.c_uint32, []),
            "PeerProcessLssInitState": (c.c_uint32, []),
            "PeerNodeId": (c.c_uint8, []),
            "PeerStackVersion": (c.c_uint32, []),
            "PeerAdvanceTicks": (None, [c.c_uint32]),
            "PeerTicks": (c.c_uint32, []),
            "PeerInject": (c.c_int, [c.c_uint32, c.c_uint8, c.c_uint8, u8p]),
            "PeerTakeSent": (c.c_int, [u32p, u8p, u8p, u8p]),
            "PeerTrace": (None, [c.c_int]),
            "PeerRead": (c.c_uint32, [c.c_uint16, c.c_uint8, c.c_void_p, u32p]),
            "PeerWrite": (c.c_uint32, [c.c_uint16, c.c_uint8, c.c_void_p, c.c_uint32]),
            "PeerNodeState": (c.c_uint8, []),
            "PeerNmtExec": (c.c_uint32, [c.c_uint16]),
            "PeerOdEntry": (c.c_int, [c.c_uint, u16p, u8p, u8p, u8p, u8p, u32p]),
            "PeerOdLimits": (c.c_int, [c.c_uint16, c.c_uint8, u8p, u8p, c.c_uint32]),
            "PeerTakeEvent": (c.c_int, [u8p, u8p, u16p, u32p]),
            "PeerSendEmergency": (c.c_uint32, [c.c_uint16, c.c_uint8, u8p]),
            "PeerHbcDefine": (c.c_uint32, [c.c_uint8, c.c_uint16, c.c_uint8]),
            "PeerHbcNodeState": (c.c_uint32, [c.c_uint8, u8p]),
            "PeerNmtmCommand": (c.c_uint32, [c.c_uint8, c.c_uint16]),
            "PeerSdocDefine": (c.c_uint32, [c.c_uint8, c.c_uint32, c.c_uint32, c.c_uint32]),
            "PeerSdocStart": (c.c_uint32, [c.c_uint16, c.c_uint8, c.c_int, u8p, c.c_uint32]),
            "PeerSdocState": (c.c_uint32, [u32p, u32p]),
            "PeerSdocBytes": (c.c_uint32, [u32p]),
            "PeerSdocData": (c.c_uint32, [u8p, c.c_uint32]),
            "PeerSendSrdo": (c.c_uint32, [c.c_uint16]),
            "PeerCalcSrdoCrc": (c.c_uint32, [c.c_uint16, u16p]),
            "PeerCheckSrdoConfig": (c.c_uint32, [u16p]),
            "PeerSrdoState": (c.c_uint32, [c.c_uint16, u8p]),
            "PeerDynBuildOd": (c.c_uint32, [u32p]),
            "PeerDynDestroyOd": (c.c_uint32, []),
            "PeerDynContainerSize": (c.c_uint32, []),
            "PeerStoreUse": (c.c_uint32, [c.c_int]),
            "PeerInitStoreResult": (c.c_uint32, []),
        }
        for name, (res, args) in sig.items():
            f = getattr(self.lib, name)
            f.restype = res
            f.argtypes = args

    # ---- clock and processing ---------------------------------------------------

    def _sync_clock(self):
        target = int((time.monotonic() - self._t0) * TICKS_PER_SECOND) + self._offset_ticks
        if target > self._ticks:
            self.lib.PeerAdvanceTicks(target - self._ticks)
            self._ticks = target

    def _collect(self):
        """Moves the node's frames and callback events into Python."""
        ident, rtr, dlc = ctypes.c_uint32(), ctypes.c_uint8(), ctypes.c_uint8()
        data = (ctypes.c_uint8 * 8)()
        while self.lib.PeerTakeSent(ctypes.byref(ident), ctypes.byref(rtr), ctypes.byref(dlc), data):
            msg = can.Message(
                timestamp=time.time(),
                arbitration_id=ident.value & 0x1FFFFFFF,
                is_extended_id=bool(ident.value & 0x20000000),
                is_remote_frame=bool(rtr.value),
                dlc=dlc.value,
                data=bytes(data[: dlc.value]) if not rtr.value else None,
                channel="cop",
            )
            self.sent.append(msg)
            self.trace.append(("node", msg))
        kind, node, index, code = ctypes.c_uint8(), ctypes.c_uint8(), ctypes.c_uint16(), ctypes.c_uint32()
        while self.lib.PeerTakeEvent(
            ctypes.byref(kind), ctypes.byref(node), ctypes.byref(index), ctypes.byref(code)
        ):
            self.events.append(Event(kind.value, node.value, index.value, code.value))

    def pump(self):
        """One CcmProcess at the current time; collects frames and events."""
        with self.lock:
            self._sync_clock()
            ret = self.lib.PeerProcess()
            self._collect()
            return ret

    def process_lss_init(self):
        """One CcmProcessLssInitState at the current time (its return code)."""
        return self._call("PeerProcessLssInitState")

    def node_id(self):
        """CcmLsssGetNodeId."""
        return self._call("PeerNodeId")

    def advance_ms(self, ms):
        """Moves the node's clock ms ahead of the wall clock and processes."""
        with self.lock:
            self._offset_ticks += int(ms * TICKS_PER_SECOND / 1000)
            self.pump()

    def ticks(self):
        with self.lock:
            return self.lib.PeerTicks()

    def _call(self, name, *args):
        with self.lock:
            self._sync_clock()
            ret = getattr(self.lib, name)(*args)
            self._collect()
            return ret

    def _check(self, name, *args):
        ret = self._call(name, *args)
        if ret != K_SUCCESSFUL:
            raise CopError(name, ret)
        return ret

    # ---- life cycle --------------------------------------------------------------

    def init(self, node_id):
        """A fresh node (INITIALISATION) on an empty bus, clock at 0."""
        with self.lock:
            self.sent.clear()
            self.events.clear()
            self.trace.clear()
            self._t0 = time.monotonic()
            self._ticks = 0
            self._offset_ticks = 0
            ret = self.lib.PeerInit(node_id)
            self._collect()
            if ret != K_SUCCESSFUL:
                raise CopError("PeerInit", ret)

    def connect(self):
        """CcmConnectToNet: PRE-OPERATIONAL, boot-up message."""
        self._check("PeerConnect")

    def connect_code(self):
        """CcmConnectToNet's return code (no exception)."""
        return self._call("PeerConnect")

    def shutdown(self):
        with self.lock:
            self.lib.PeerShutdown()

    def store_use(self, on):
        """Registers (True) or removes and erases (False) the simulated memory."""
        self._check("PeerStoreUse", 1 if on else 0)

    def init_store_result(self):
        """What CcmInitStore returned in the last start-up."""
        return self.lib.PeerInitStoreResult()

    def stack_version(self):
        return self.lib.PeerStackVersion()

    def set_trace(self, on):
        self.lib.PeerTrace(1 if on else 0)

    # ---- bus ---------------------------------------------------------------------------

    def inject(self, msg):
        """Puts a frame of the Python side on the bus and processes it."""
        with self.lock:
            self.trace.append(("python", msg))
            data = (ctypes.c_uint8 * 8)(*bytes(msg.data or b""))
            ident = msg.arbitration_id | (0x20000000 if msg.is_extended_id else 0)
            self._sync_clock()
            self.lib.PeerInject(ident, 1 if msg.is_remote_frame else 0, msg.dlc, data)
            self.lib.PeerProcess()
            self._collect()

    def candump(self):
        """The frames of this scenario in candump form (for failure reports)."""
        lines = []
        for who, m in self.trace:
            data = "remote request" if m.is_remote_frame else " ".join(f"{b:02X}" for b in m.data)
            lines.append(f"  can0  {m.arbitration_id:03X}   [{m.dlc}]  {data}    ({who})")
        return "\n".join(lines)

    # ---- dictionary ------------------------------------------------------------------------

    def read(self, index, sub, capacity=1024):
        """CcmReadObject: the value in CPU (= little-endian) byte order."""
        buf = (ctypes.c_uint8 * capacity)()
        size = ctypes.c_uint32(capacity)
        self._check("PeerRead", index, sub, buf, ctypes.byref(size))
        return bytes(buf[: size.value])

    def write(self, index, sub, data):
        """CcmWriteObject; raises CopError with the library's code."""
        buf = (ctypes.c_uint8 * max(1, len(data)))(*data)
        self._check("PeerWrite", index, sub, buf, len(data))

    def node_state(self):
        with self.lock:
            return self.lib.PeerNodeState()

    def od_entries(self):
        """The library's dictionary tables: (index, sub, type, access, kind, size)."""
        out = []
        n = 0
        w, b = ctypes.c_uint16, ctypes.c_uint8
        while True:
            index, sub, typ, acc, kind, size = w(), b(), b(), b(), b(), ctypes.c_uint32()
            found = self.lib.PeerOdEntry(
                n,
                ctypes.byref(index),
                ctypes.byref(sub),
                ctypes.byref(typ),
                ctypes.byref(acc),
                ctypes.byref(kind),
                ctypes.byref(size),
            )
            if not found:
                return out
            out.append((index.value, sub.value, typ.value, acc.value, kind.value, size.value))
            n += 1

    def od_limits(self, index, sub):
        """Native bytes of (low, high) of a range-checked object, or None."""
        low, high = (ctypes.c_uint8 * 8)(), (ctypes.c_uint8 * 8)()
        n = self.lib.PeerOdLimits(index, sub, low, high, 8)
        if n < 0:
            return None
        return bytes(low[:n]), bytes(high[:n])

    # ---- events -------------------------------------------------------------------------------

    def take_events(self, kind=None):
        """Events since the last call (of one kind, or all), oldest first."""
        with self.lock:
            self._collect()
            if kind is None:
                out, self.events = self.events, []
            else:
                out = [e for e in self.events if e.kind == kind]
                self.events = [e for e in self.events if e.kind != kind]
            return out

    def send_emergency(self, code, register, manufacturer=bytes(5)):
        buf = (ctypes.c_uint8 * 5)(*manufacturer)
        self._check("PeerSendEmergency", code, register, buf)

    # ---- heartbeat consumer, NMT master --------------------------------------------------------

    def hbc_define(self, node, time_ms, subindex):
        self._check("PeerHbcDefine", node, time_ms, subindex)

    def hbc_node_state(self, node):
        """The state the consumer last heard from node, or None."""
        st = ctypes.c_uint8()
        ret = self._call("PeerHbcNodeState", node, ctypes.byref(st))
        return st.value if ret == K_SUCCESSFUL else None

    def nmtm_command(self, node, command):
        self._check("PeerNmtmCommand", node, command)

    # ---- SDO client ------------------------------------------------------------------------------

    def sdoc_define(self, server, tx_cobid, rx_cobid, timeout_ms):
        self._check("PeerSdocDefine", server, tx_cobid, rx_cobid, timeout_ms * TICKS_PER_SECOND // 1000)

    def sdoc_start(self, index, sub, upload, data=b"", length=None, block=False):
        """CcmSdocStartTransfer: segmented (expedited when short) or, with
        block, kSdocTypeBlockDown / kSdocTypeBlockUp."""
        length = len(data) if length is None else length
        buf = (ctypes.c_uint8 * max(1, len(data)))(*data)
        sdoc_type = (3 if upload else 2) if block else (1 if upload else 0)
        self._check("PeerSdocStart", index, sub, sdoc_type, buf, length)

    def sdoc_state(self):
        """(tSdocState, abort code) of channel 0x1280."""
        st, ab = ctypes.c_uint32(), ctypes.c_uint32()
        self._check("PeerSdocState", ctypes.byref(st), ctypes.byref(ab))
        return st.value, ab.value

    def sdoc_bytes(self):
        n = ctypes.c_uint32()
        self._check("PeerSdocBytes", ctypes.byref(n))
        return n.value

    def sdoc_data(self, n):
        buf = (ctypes.c_uint8 * n)()
        got = self._call("PeerSdocData", buf, n)
        return bytes(buf[:got])

    # ---- SRDO ----------------------------------------------------------------------------------------

    def send_srdo(self, index):
        """CcmSendSrdo; returns the tCopKernel (no exception)."""
        return self._call("PeerSendSrdo", index)

    def calc_srdo_crc(self, index):
        crc = ctypes.c_uint16()
        self._check("PeerCalcSrdoCrc", index, ctypes.byref(crc))
        return crc.value

    def check_srdo_config(self):
        """(tCopKernel, communication index of the first bad SRDO)."""
        idx = ctypes.c_uint16()
        ret = self._call("PeerCheckSrdoConfig", ctypes.byref(idx))
        return ret, idx.value

    def srdo_state(self, index):
        st = ctypes.c_uint8()
        self._check("PeerSrdoState", index, ctypes.byref(st))
        return st.value

    # ---- dynamic object dictionary -------------------------------------------------------------------------

    PROCESS_IMAGE_SIZE = 64  # PEER_PROCESS_IMAGE_SIZE

    def dyn_build(self):
        """DynBuildOd with the container of peer/peer_dynod.dcf; returns the
        process image description (size, input offset, input size, output
        offset, output size) or raises CopError."""
        pi = (ctypes.c_uint32 * 5)()
        self._check("PeerDynBuildOd", pi)
        return tuple(pi)

    def dyn_destroy(self):
        self._check("PeerDynDestroyOd")

    def dyn_container_size(self):
        return self.lib.PeerDynContainerSize()

    def process_image(self):
        """The process image handed to DynBuildOd (a ctypes array, read and
        written under the lock)."""
        return self.var(ctypes.c_uint8 * self.PROCESS_IMAGE_SIZE, "abPeerProcessImage_g")

    # ---- application variables ---------------------------------------------------------------------------

    def var(self, ctype, name):
        """An application variable of peer_harness.c (read it under the lock)."""
        return ctype.in_dll(self.lib, name)


class CopBus(can.BusABC):
    """python-can bus whose only other node is the library (``PeerLibrary``)."""

    POLL_S = 0.001

    def __init__(self, peer, **kwargs):
        self.peer = peer
        self.channel_info = "cop simulated CAN bus"
        super().__init__(channel="cop", **kwargs)

    def send(self, msg, timeout=None):
        self.peer.inject(msg)

    def _recv_internal(self, timeout):
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            with self.peer.lock:
                if not self.peer.sent:
                    self.peer.pump()
                if self.peer.sent:
                    return self.peer.sent.popleft(), False
            if deadline is not None:
                left = deadline - time.monotonic()
                if left <= 0:
                    return None, False
                time.sleep(min(self.POLL_S, left))
            else:
                time.sleep(self.POLL_S)
