//! What the stack reports to the application, and the queue that orders it.
//!
//! The stack never calls the application while it is in the middle of a
//! change: [`crate::ccm::Stack::poll`] returns one [`Event`] at a time and
//! the caller handles it (on the C side: calls `AppSrdoEvent`, the NMT
//! callback, ...) before calling `poll` again. The application may
//! therefore call back into the API (`CcmGetSrdoState`, `CcmWriteObject`)
//! from inside its callbacks and always sees the state the event describes.

use crate::error::CopKernel;

c_enum! {
    /// NMT states (`kNodeState*`, CiA 301 values).
    pub enum NmtState: u8, fn from_u8(u8) {
        /// Initialisation (before `CcmConnectToNet`).
        Initialisation = 0x00,
        /// Stopped.
        Stopped = 0x04,
        /// Operational.
        Operational = 0x05,
        /// Pre-operational.
        PreOperational = 0x7F,
    }
}

c_enum! {
    /// NMT events passed to the application's NMT callback (`tNmtEvent`).
    pub enum NmtEvent: u8, fn from_u8(u8) {
        /// kNmtEvEnterInitialising.
        EnterInitialising = 0x01,
        /// kNmtEvResetNode: application objects were reset to their defaults.
        ResetNode = 0x02,
        /// kNmtEvPreResetCommunication: communication objects are about to be reset.
        PreResetCommunication = 0x03,
        /// kNmtEvResetCommunication: communication objects have their defaults;
        /// the application (re)writes its configuration now.
        ResetCommunication = 0x04,
        /// kNmtEvPostResetCommunication: the modules took over the configuration.
        PostResetCommunication = 0x05,
        /// kNmtEvEnterPreOperational.
        EnterPreOperational = 0x10,
        /// kNmtEvEnterOperational.
        EnterOperational = 0x20,
        /// kNmtEvEnterStopped.
        EnterStopped = 0x30,
    }
}

c_enum! {
    /// Program-flow monitor events (`tProgMonEvent`, manual 2.9.4).
    pub enum ProgMonEvent: u8, fn from_u8(u8) {
        /// kSrdoPMEvSctChecked: the SCT of a receive SRDO was checked.
        SctChecked = 0x01,
        /// kSrdoPMEvSctNotCheckedItIsTx.
        SctNotCheckedItIsTx = 0x02,
        /// kSrdoPMEvSctNotCheckedItIsInvalid.
        SctNotCheckedItIsInvalid = 0x03,
        /// kSrdoPMEvSctNotCheckedNotOperational.
        SctNotCheckedNotOperational = 0x04,
        /// kSrdoPMEvSrdoError.
        SrdoError = 0x05,
        /// kSrdoPMEvSrdoReceived.
        SrdoReceived = 0x06,
        /// kSrdoPMEvSrdoTransmitted.
        SrdoTransmitted = 0x07,
    }
}

c_enum! {
    /// NMT error control events (`tNmtErrCtrlEvent`).
    #[allow(missing_docs)]
    pub enum ErrCtrlEvent: u8, fn from_u8(u8) {
        Idle = 0x00,
        LgConnected = 0x10,
        LgMsgLost = 0x11,
        LgLostConnection = 0x12,
        BootupReceived = 0x20,
        LgNodeStateChanged = 0x31,
        LgToggleError = 0x32,
        LgSuspended = 0x33,
        LgNoAnswer = 0x34,
        HbcConnected = 0x40,
        HbcConnectionLost = 0x41,
        HbcNodeStateChanged = 0x42,
        Unknown = 0xFF,
    }
}

/// An event for the application.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// The NMT callback (`m_fpNmtEventCallback`).
    Nmt(NmtEvent),
    /// `AppSrdoEvent(commu_index)`: an SRDO was received or sent correctly.
    SrdoEvent(u16),
    /// `AppSrdoError(commu_index, code)`.
    SrdoError(u16, CopKernel),
    /// `AppGfcEvent()`.
    Gfc,
    /// `AppProgMonEvent(event)`.
    ProgMon(ProgMonEvent),
    /// Heartbeat consumer event for a node.
    Hbc(u8, ErrCtrlEvent),
    /// NMT master event for a node (boot-up, life guarding).
    Nmtm(u8, ErrCtrlEvent),
    /// An SDO client transfer finished (client index, state, abort code).
    SdocFinished {
        /// Client index (0x1280 + n).
        client: u16,
        /// `tSdocState`.
        state: u8,
        /// Abort code, 0 on success.
        abort: u32,
    },
    /// An emergency message was received from a node (consumer).
    Emcc(u8, crate::wire::emcy::Emergency),
    /// The PDO callback (`tPdoCallback(commu_index)`) of a PDO defined with
    /// one: an RPDO's data reached its variables, or a TPDO was sent.
    Pdo(u16),
}

/// Work the stack does between two events (never visible to the caller).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    /// Restore the defaults of the application objects (0x2000–0x9FFF).
    RestoreApplication,
    /// Restore the defaults of the communication objects (0x1000–0x1FFF).
    RestoreCommunication,
    /// Let every module read its configuration from the dictionary.
    Reconfigure,
    /// Switch to an NMT state (boot-up is sent when leaving initialisation).
    EnterState(NmtState),
    /// After `AppSrdoError` for an SRDO (table slot): check the status bits
    /// 6-7 the application had to set (manual 2.9.2).
    SrdoCheckHandled(u8),
    /// A successful transfer of an SRDO (table slot) whose event waits in
    /// the queue: status bits 4-5 := 00 ("ok") when its turn comes, then
    /// `Event::SrdoEvent`, so that its callback finds the status of its own
    /// transfer whatever an earlier callback set meanwhile.
    SrdoOk(u8),
}

/// An entry of the action queue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Hand an event to the application.
    Emit(Event),
    /// Do internal work.
    Do(Internal),
}

/// Capacity of the action queue. A step of the stack (one received frame,
/// one timer check, one API call) queues at most this many actions; the
/// stack starts a new step only when the queue is empty.
pub const QUEUE_CAPACITY: usize = 16;

/// A fixed-capacity double-ended queue of actions.
#[derive(Clone, Debug)]
pub struct ActionQueue {
    /// The ring; only the `len` entries from `head` count (the others hold
    /// whatever was there).
    buf: [Action; QUEUE_CAPACITY],
    head: usize,
    len: usize,
}

impl Default for ActionQueue {
    fn default() -> Self {
        Self::new()
    }
}

impl ActionQueue {
    /// An empty queue.
    pub const fn new() -> Self {
        ActionQueue {
            buf: [Action::Do(Internal::Reconfigure); QUEUE_CAPACITY],
            head: 0,
            len: 0,
        }
    }

    /// Number of queued actions.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when nothing is queued.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends an action. Returns `false` (and drops nothing already queued)
    /// when the queue is full; callers size their steps so this never
    /// happens, and a test asserts it.
    pub fn push(&mut self, a: Action) -> bool {
        if self.len == QUEUE_CAPACITY {
            return false;
        }
        let slot = (self.head + self.len) % QUEUE_CAPACITY;
        if let Some(s) = self.buf.get_mut(slot) {
            *s = a;
        }
        self.len += 1;
        true
    }

    /// Appends an event.
    pub fn emit(&mut self, e: Event) -> bool {
        self.push(Action::Emit(e))
    }

    /// Appends internal work.
    pub fn schedule(&mut self, i: Internal) -> bool {
        self.push(Action::Do(i))
    }

    /// Puts an action in front of everything queued.
    pub fn push_front(&mut self, a: Action) -> bool {
        if self.len == QUEUE_CAPACITY {
            return false;
        }
        self.head = (self.head + QUEUE_CAPACITY - 1) % QUEUE_CAPACITY;
        if let Some(s) = self.buf.get_mut(self.head) {
            *s = a;
        }
        self.len += 1;
        true
    }

    /// Takes the first action (copied out; its slot is simply left behind,
    /// only the `len` slots from `head` count).
    #[inline]
    pub fn pop(&mut self) -> Option<Action> {
        if self.len == 0 {
            return None;
        }
        let a = self.buf.get(self.head % QUEUE_CAPACITY).copied();
        self.head = (self.head + 1) % QUEUE_CAPACITY;
        self.len -= 1;
        a
    }

    /// Whether the first action is a program monitor event.
    #[inline(always)]
    pub fn front_is_progmon(&self) -> bool {
        self.len != 0
            && matches!(
                self.buf.get(self.head % QUEUE_CAPACITY),
                Some(Action::Emit(Event::ProgMon(_)))
            )
    }

    /// Takes the first action when it is a program monitor event.
    #[inline(always)]
    pub fn pop_progmon(&mut self) -> Option<ProgMonEvent> {
        if self.len == 0 {
            return None;
        }
        let Some(Action::Emit(Event::ProgMon(e))) =
            self.buf.get(self.head % QUEUE_CAPACITY).copied()
        else {
            return None;
        };
        self.head = (self.head + 1) % QUEUE_CAPACITY;
        self.len -= 1;
        Some(e)
    }

    /// Takes the first action when it is an event for the application
    /// (internal work stays queued), as [`ActionQueue::pop`].
    #[inline]
    pub fn pop_event(&mut self) -> Option<Event> {
        if self.len == 0 {
            return None;
        }
        let Some(Action::Emit(e)) = self.buf.get(self.head % QUEUE_CAPACITY).copied() else {
            return None;
        };
        self.head = (self.head + 1) % QUEUE_CAPACITY;
        self.len -= 1;
        Some(e)
    }

    /// Drops everything.
    pub fn clear(&mut self) {
        *self = Self::new();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fifo_with_front_insertion() {
        let mut q = ActionQueue::new();
        assert!(q.emit(Event::Gfc));
        assert!(q.schedule(Internal::Reconfigure));
        assert!(q.push_front(Action::Emit(Event::SrdoEvent(0x1301))));
        assert_eq!(q.pop(), Some(Action::Emit(Event::SrdoEvent(0x1301))));
        assert_eq!(q.pop(), Some(Action::Emit(Event::Gfc)));
        assert_eq!(q.pop(), Some(Action::Do(Internal::Reconfigure)));
        assert_eq!(q.pop(), None);
    }

    #[test]
    fn events_are_taken_before_internal_work_only_in_order() {
        let mut q = ActionQueue::new();
        assert_eq!(q.pop_event(), None);
        assert!(q.emit(Event::Gfc));
        assert!(q.schedule(Internal::Reconfigure));
        assert!(q.emit(Event::SrdoEvent(0x1301)));
        assert_eq!(q.pop_event(), Some(Event::Gfc));
        // Internal work in front: nothing is taken.
        assert_eq!(q.pop_event(), None);
        assert_eq!(q.len(), 2);
        assert_eq!(q.pop(), Some(Action::Do(Internal::Reconfigure)));
        assert_eq!(q.pop_event(), Some(Event::SrdoEvent(0x1301)));
        assert!(q.is_empty());
        // Around the end of the ring.
        for i in 0..3 * QUEUE_CAPACITY as u16 {
            assert!(q.emit(Event::SrdoEvent(i)));
            assert_eq!(q.pop_event(), Some(Event::SrdoEvent(i)));
        }
        assert!(q.is_empty());
    }

    #[test]
    fn full_queue_refuses_without_losing() {
        let mut q = ActionQueue::new();
        for _ in 0..QUEUE_CAPACITY {
            assert!(q.emit(Event::Gfc));
        }
        assert!(!q.emit(Event::SrdoEvent(1)));
        assert!(!q.push_front(Action::Emit(Event::SrdoEvent(1))));
        assert_eq!(q.len(), QUEUE_CAPACITY);
        for _ in 0..QUEUE_CAPACITY {
            assert_eq!(q.pop(), Some(Action::Emit(Event::Gfc)));
        }
        assert!(q.is_empty());
    }
}
