//! Values kept under the keys they were computed for: a stage's outputs under their inputs, or a run under
//! way (a paused equilibrium, a THD loop, a sweep) under the inputs it works towards.

/// Up to `capacity` values, each under its key; a lookup with another key finds nothing. When full, a new
/// key pushes out the one used least recently.
#[derive(Debug, Clone)]
pub struct Cached<K, T> {
    /// Least recently used first.
    entries: Vec<(K, T)>,
    capacity: usize,
}

impl<K, T> Default for Cached<K, T> {
    fn default() -> Self {
        Self::keeping(1)
    }
}

impl<K, T> Cached<K, T> {
    /// A cache of at most `capacity` values (at least one).
    #[must_use]
    pub fn keeping(capacity: usize) -> Self {
        Self { entries: Vec::new(), capacity: capacity.max(1) }
    }

    /// The values kept.
    #[must_use]
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}

impl<K: PartialEq, T> Cached<K, T> {
    fn position(&self, key: &K) -> Option<usize> {
        self.entries.iter().rposition(|(k, _)| k == key)
    }

    /// The value, if it was computed for `key`.
    #[must_use]
    pub fn get(&self, key: &K) -> Option<&T> {
        self.position(key).map(|i| &self.entries[i].1)
    }

    /// The value to update in place, if it was computed for `key` (it becomes the most recently used).
    pub fn get_mut(&mut self, key: &K) -> Option<&mut T> {
        let i = self.position(key)?;
        let entry = self.entries.remove(i);
        self.entries.push(entry);
        self.entries.last_mut().map(|(_, v)| v)
    }

    /// Keeps `value` under `key` (replacing a value under the same key; when full, dropping the least
    /// recently used one).
    pub fn put(&mut self, key: K, value: T) {
        if let Some(i) = self.position(&key) {
            self.entries.remove(i);
        }
        if self.entries.len() >= self.capacity {
            self.entries.remove(0);
        }
        self.entries.push((key, value));
    }

    /// The value under `key`, made by `make` (and kept) if there is none.
    ///
    /// # Errors
    /// `make`'s.
    pub fn get_or_try_insert<E>(&mut self, key: &K, make: impl FnOnce() -> Result<T, E>) -> Result<&mut T, E>
    where
        K: Clone,
    {
        if self.position(key).is_none() {
            let value = make()?;
            self.put(key.clone(), value);
        }
        let i = self.position(key).unwrap_or(self.entries.len() - 1);
        let entry = self.entries.remove(i);
        self.entries.push(entry);
        let last = self.entries.len() - 1;
        Ok(&mut self.entries[last].1)
    }

    /// Takes the value out if it was computed for `key`; with room for one value, a value for another key
    /// is dropped too (it is stale).
    pub fn take(&mut self, key: &K) -> Option<T> {
        let taken = self.position(key).map(|i| self.entries.remove(i).1);
        if self.capacity == 1 {
            self.entries.clear();
        }
        taken
    }

    /// The most recent value whatever its key (a warm start from the last solve).
    #[must_use]
    pub fn any(&self) -> Option<&T> {
        self.entries.last().map(|(_, v)| v)
    }

    /// Drops every value.
    pub fn clear(&mut self) {
        self.entries.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::Cached;

    #[test]
    fn a_value_is_found_only_under_its_key() {
        let mut c = Cached::default();
        assert_eq!(c.get(&1), None);
        c.put(1, "a");
        assert_eq!(c.get(&1), Some(&"a"));
        assert_eq!(c.get(&2), None);
        assert_eq!(c.any(), Some(&"a"));
        // Taking with another key drops the stale value.
        assert_eq!(c.take(&2), None);
        assert_eq!(c.any(), None);
        c.put(3, "b");
        assert_eq!(c.take(&3), Some("b"));
    }

    #[test]
    fn a_larger_cache_keeps_the_most_recently_used_values() {
        let mut c = Cached::keeping(2);
        c.put(1, "a");
        c.put(2, "b");
        // Using 1 makes 2 the least recently used: a third key pushes 2 out.
        assert!(c.get_mut(&1).is_some());
        c.put(3, "c");
        assert_eq!((c.get(&1), c.get(&2), c.get(&3)), (Some(&"a"), None, Some(&"c")));
        assert_eq!(c.len(), 2);
        // The same key replaces its value.
        c.put(3, "d");
        assert_eq!((c.get(&3), c.len()), (Some(&"d"), 2));
        // Taking one value keeps the others.
        assert_eq!(c.take(&1), Some("a"));
        assert_eq!((c.get(&3), c.len()), (Some(&"d"), 1));
    }
}
