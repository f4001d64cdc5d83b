//! Master-side callbacks (heartbeat consumer, NMT master, SDO client,
//! emergency consumer). The core does not produce these events yet; they
//! are ignored until the master services are registered.

use crate::event::Event;

/// Calls the application for a master-side event.
pub fn dispatch(ev: Event) {
    let _ = ev;
}
