//! A map keyed by primitive ID. IDs are `PRIMITIVE_ID_BASE + table index`
//! ([`crate::model`]), so an entry is found by indexing instead of a search: the servo
//! step and the sensor snapshot look joints up dozens of times a frame. Iteration is in
//! ID order, as a `BTreeMap`'s was, so traces keep their order.
use crate::model::{PrimitiveId, PRIMITIVE_ID_BASE};

#[derive(Clone, Debug)]
pub struct IdMap<T> {
    slots: Vec<Option<T>>,
}

impl<T> Default for IdMap<T> {
    fn default() -> Self {
        IdMap { slots: Vec::new() }
    }
}

fn index(id: PrimitiveId) -> Option<usize> {
    id.checked_sub(PRIMITIVE_ID_BASE).map(|i| i as usize)
}

impl<T> IdMap<T> {
    /// Sets `id`'s entry. IDs below the base have no slot and are ignored (no table
    /// row has one).
    pub fn insert(&mut self, id: PrimitiveId, v: T) {
        let Some(i) = index(id) else { return };
        if i >= self.slots.len() {
            self.slots.resize_with(i + 1, || None);
        }
        self.slots[i] = Some(v);
    }

    pub fn get(&self, id: &PrimitiveId) -> Option<&T> {
        self.slots.get(index(*id)?)?.as_ref()
    }

    pub fn get_mut(&mut self, id: &PrimitiveId) -> Option<&mut T> {
        self.slots.get_mut(index(*id)?)?.as_mut()
    }

    pub fn keys(&self) -> impl Iterator<Item = PrimitiveId> + '_ {
        self.slots.iter().enumerate().filter(|(_, s)| s.is_some()).map(|(i, _)| PRIMITIVE_ID_BASE + i as u32)
    }

    pub fn values_mut(&mut self) -> impl Iterator<Item = &mut T> {
        self.slots.iter_mut().flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_by_id_in_id_order() {
        let mut m = IdMap::default();
        m.insert(PRIMITIVE_ID_BASE + 5, 'b');
        m.insert(PRIMITIVE_ID_BASE + 1, 'a');
        m.insert(PRIMITIVE_ID_BASE - 1, 'x');
        assert_eq!(m.get(&(PRIMITIVE_ID_BASE + 5)), Some(&'b'));
        assert_eq!(m.get(&(PRIMITIVE_ID_BASE + 2)), None);
        assert_eq!(m.get(&(PRIMITIVE_ID_BASE + 99)), None);
        assert_eq!(m.get(&0), None, "below the base");
        *m.get_mut(&(PRIMITIVE_ID_BASE + 1)).unwrap() = 'c';
        assert_eq!(m.keys().collect::<Vec<_>>(), [PRIMITIVE_ID_BASE + 1, PRIMITIVE_ID_BASE + 5]);
        assert_eq!(m.values_mut().map(|v| *v).collect::<String>(), "cb");
    }
}
