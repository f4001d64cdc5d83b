//! Emergency consumer (CiA 301 7.2.7): the SYS TEC module EMCC
//! (`CcmInitEmcc`, `CcmInitEmccEx`, `CcmEmccDefineProducerTab`).
//!
//! The application lists the producers it listens to by node-ID; each
//! producer's emergency object arrives on COB-ID 0x80 + node-ID (the
//! predefined connection set, CiA 301 7.3.4). Every valid emergency frame
//! (DLC 8, decoded by [`crate::wire::emcy`]) from a listed producer becomes
//! one [`Event::Emcc`], in the order received.
//!
//! # Behaviour decisions
//! * The table is replaced as a whole by each definition, so the call may
//!   be repeated (for example at every kNmtEvResetCommunication). A refused
//!   table leaves the previous one in force.
//! * This node's own ID is refused (kCopEmccNodeIdInvalid): a CAN
//!   controller does not receive its own frames, so the entry could never
//!   report anything.
//! * Identifiers are handed to the driver when a producer enters the table
//!   and are never withdrawn (the same identifier may serve a PDO or the
//!   SYNC consumer); frames of a producer no longer listed are ignored.
//! * Reception follows the NMT state rules of the EMCY object (CiA 301
//!   7.3.2.2): PRE-OPERATIONAL and OPERATIONAL only.
//! * Frames with another length, and remote frames, are not emergencies
//!   and are left to the other services.

use crate::error::{CopKernel, CopResult};
use crate::event::{ActionQueue, Event};
use crate::port::{CanFrame, CanId, CanPort, Priority};
use crate::wire::emcy::{self, EMCY_BASE};

/// Capacity: `EMCC_MAX_CONSUMER` (producers the consumer can list).
pub const CAPACITY: usize = crate::config::EMCC_MAX_CONSUMER;

/// The emergency consumer.
#[derive(Clone, Debug)]
pub struct EmcyConsumer {
    enabled: bool,
    /// Node-IDs of the listed producers; 0 marks a free entry.
    producers: [u8; CAPACITY],
}

crate::od::decl::default_is_new!(EmcyConsumer);

/// The COB-ID on which `node` sends its emergencies.
pub const fn producer_id(node: u8) -> CanId {
    CanId::std_masked(EMCY_BASE + node as u16)
}

impl EmcyConsumer {
    /// A disabled consumer without producers.
    pub const fn new() -> Self {
        EmcyConsumer {
            enabled: false,
            producers: [0; CAPACITY],
        }
    }

    /// `CcmInitEmcc` / `CcmInitEmccEx`: received emergencies are reported
    /// from now on.
    pub fn enable(&mut self) {
        self.enabled = true;
    }

    /// True after [`EmcyConsumer::enable`].
    pub fn is_enabled(&self) -> bool {
        self.enabled
    }

    /// The listed producers, in table order.
    pub fn producers(&self) -> impl Iterator<Item = u8> + '_ {
        self.producers.iter().copied().filter(|n| *n != 0)
    }

    /// `CcmEmccDefineProducerTab`: the producers to listen to, replacing
    /// the previous list; `own` is this node's ID; node-ID 0 marks an
    /// unused entry and is skipped. Codes, checked in this
    /// order: kCopEmccNoFreeProducerEntry (more entries than
    /// `EMCC_MAX_CONSUMER`), kCopEmccNodeIdInvalid (not 1..=127, or this
    /// node), kCopEmccNodeIdExist (a node listed twice). New identifiers
    /// are subscribed at the driver; its refusal is returned after the
    /// table has been taken over.
    pub fn define_producers(
        &mut self,
        nodes: &[u8],
        own: u8,
        port: &mut impl CanPort,
    ) -> CopResult {
        // Node-ID 0 marks an unused entry of the application's table
        // (tables sized for every possible slave, filled as slaves are
        // added): skipped, not refused.
        let used = || nodes.iter().filter(|n| **n != 0);
        if used().count() > CAPACITY {
            return Err(CopKernel::EmccNoFreeProducerEntry);
        }
        for (i, n) in used().enumerate() {
            if !(1..=127).contains(n) || *n == own {
                return Err(CopKernel::EmccNodeIdInvalid);
            }
            if used().take(i).any(|m| m == n) {
                return Err(CopKernel::EmccNodeIdExist);
            }
        }
        let previous = self.producers;
        self.producers = [0; CAPACITY];
        let mut result = Ok(());
        for (slot, n) in self.producers.iter_mut().zip(used()) {
            *slot = *n;
            if !previous.contains(n) {
                if let Err(e) = port.subscribe(producer_id(*n), Priority::Low) {
                    result = result.and(Err(e));
                }
            }
        }
        result
    }

    /// True when the used entries of `nodes` (node-IDs other than 0), in
    /// their order, are the listed producers.
    pub fn same_producers(&self, nodes: &[u8]) -> bool {
        let listed = self.producers.iter().copied().filter(|n| *n != 0);
        listed.eq(nodes.iter().copied().filter(|n| *n != 0))
    }

    /// Offers a received frame; `true` when it was an emergency of a
    /// listed producer (queued as [`Event::Emcc`]). The caller applies the
    /// NMT state rule.
    pub fn on_frame(&self, f: &CanFrame, q: &mut ActionQueue) -> bool {
        if !self.enabled || f.id.is_extended() {
            return false;
        }
        let Some(node) =
            f.id.id()
                .checked_sub(u32::from(EMCY_BASE))
                .and_then(|n| u8::try_from(n).ok())
        else {
            return false;
        };
        if node == 0 || !self.producers.contains(&node) {
            return false;
        }
        match emcy::decode(f) {
            Some(e) => q.emit(Event::Emcc(node, e)),
            None => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::event::Action;
    use crate::wire::emcy::Emergency;

    struct Filter(Vec<CanId>);
    impl CanPort for Filter {
        fn send(&mut self, _: &CanFrame, _: Priority) -> CopResult {
            Ok(())
        }
        fn receive(&mut self) -> Option<crate::port::RxFrame> {
            None
        }
        fn subscribe(&mut self, id: CanId, _: Priority) -> CopResult {
            self.0.push(id);
            Ok(())
        }
    }

    #[test]
    fn table_codes_in_order_and_refusal_keeps_the_table() {
        let mut c = EmcyConsumer::new();
        let mut f = Filter(Vec::new());
        assert!(c.define_producers(&[5], 1, &mut f).is_ok());
        let too_many = [9u8; CAPACITY + 1];
        assert_eq!(
            c.define_producers(&too_many, 1, &mut f),
            Err(CopKernel::EmccNoFreeProducerEntry)
        );
        assert_eq!(
            c.define_producers(&[128], 1, &mut f),
            Err(CopKernel::EmccNodeIdInvalid)
        );
        assert_eq!(
            c.define_producers(&[1], 1, &mut f),
            Err(CopKernel::EmccNodeIdInvalid)
        );
        assert_eq!(
            c.define_producers(&[7, 7], 1, &mut f),
            Err(CopKernel::EmccNodeIdExist)
        );
        assert_eq!(c.producers().collect::<Vec<_>>(), vec![5]);
        // Replacing subscribes only the new identifiers; 0 = unused entry
        // (a table longer than the capacity with few entries used fits).
        let mut sparse = [0u8; CAPACITY + 3];
        sparse[1] = 5;
        sparse[CAPACITY + 2] = 6;
        assert!(c.define_producers(&sparse, 1, &mut f).is_ok());
        assert_eq!(c.producers().collect::<Vec<_>>(), vec![5, 6]);
        assert_eq!(f.0, vec![producer_id(5), producer_id(6)]);
    }

    #[test]
    fn only_listed_producers_and_dlc_8_are_emergencies() {
        let mut c = EmcyConsumer::new();
        let mut f = Filter(Vec::new());
        c.define_producers(&[5], 1, &mut f).unwrap();
        let mut q = ActionQueue::new();
        let e = Emergency {
            code: 0x8130,
            register: 0x11,
            manufacturer: [1, 2, 3, 4, 5],
        };
        let frame = emcy::encode(producer_id(5), &e);
        // Not enabled yet.
        assert!(!c.on_frame(&frame, &mut q));
        c.enable();
        assert!(c.on_frame(&frame, &mut q));
        assert_eq!(q.pop(), Some(Action::Emit(Event::Emcc(5, e))));
        assert!(!c.on_frame(&emcy::encode(producer_id(6), &e), &mut q));
        let short = CanFrame::new(producer_id(5), &[0x30, 0x81, 0x11]);
        assert!(!c.on_frame(&short, &mut q));
        let sync = CanFrame::new(CanId::std_masked(0x80), &[0; 8]);
        assert!(!c.on_frame(&sync, &mut q));
        assert!(q.is_empty());
    }
}
