//! The contact's lazily built interpolation map, behind a lock.

use std::sync::{Mutex, MutexGuard, PoisonError};

use crate::Map;

/// The contact's interpolation map ([`Options::map`]), behind a lock so that
/// [`TractionContact::evaluate`] keeps `&self` and the contact stays `Sync`.
/// A cache: cloning copies it; it has no equality (a contact's equality
/// compares its definition, see `TractionContact`'s `PartialEq`).
#[derive(Default)]
pub(crate) struct MapCache(Mutex<Option<Map>>);

impl MapCache {
    pub(crate) fn lock(&self) -> MutexGuard<'_, Option<Map>> {
        // A panic while holding the lock cannot leave the map inconsistent
        // (cells are inserted whole), so a poisoned lock is still usable.
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Clone for MapCache {
    fn clone(&self) -> Self {
        MapCache(Mutex::new(self.lock().clone()))
    }
}

impl std::fmt::Debug for MapCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MapCache({:?})", self.lock().as_ref().map(Map::stats))
    }
}
