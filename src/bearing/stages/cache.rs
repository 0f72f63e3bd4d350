//! A value kept under the key it was computed for: a stage's output under its inputs, or a run under way
//! (a paused equilibrium, a THD loop, a sweep) under the inputs it works towards.

/// One value and its key; a lookup with another key finds nothing.
#[derive(Debug, Clone)]
pub struct Cached<K, T> {
    entry: Option<(K, T)>,
}

impl<K, T> Default for Cached<K, T> {
    fn default() -> Self {
        Self { entry: None }
    }
}

impl<K: PartialEq, T> Cached<K, T> {
    /// The value, if it was computed for `key`.
    #[must_use]
    pub fn get(&self, key: &K) -> Option<&T> {
        self.entry.as_ref().filter(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// The value to update in place, if it was computed for `key`.
    pub fn get_mut(&mut self, key: &K) -> Option<&mut T> {
        self.entry.as_mut().filter(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// Keeps `value` under `key` (dropping what was there).
    pub fn put(&mut self, key: K, value: T) {
        self.entry = Some((key, value));
    }

    /// Takes the value out if it was computed for `key`; a value for another key is dropped.
    pub fn take(&mut self, key: &K) -> Option<T> {
        self.entry.take().filter(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// The value whatever its key (a warm start from the last solve).
    #[must_use]
    pub fn any(&self) -> Option<&T> {
        self.entry.as_ref().map(|(_, v)| v)
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
        // Taking with another key drops the value.
        assert_eq!(c.take(&2), None);
        assert_eq!(c.any(), None);
        c.put(3, "b");
        assert_eq!(c.take(&3), Some("b"));
    }
}
