//! Balls sorted into numbered lists (the cells of the grid, the days of the calendar), each
//! ball in at most one. Every list is linked through its balls in both directions, so putting
//! a ball in or taking it out costs O(1) whatever the list holds (Rapaport's cell lists).

/// The end of a list, or no list.
const NONE: u32 = u32::MAX;

/// Numbered lists of balls, keeping their buffers when laid out again.
#[derive(Clone, Debug, Default)]
pub(super) struct Lists {
    /// First ball of each list.
    head: Vec<u32>,
    /// Per ball: the list it is in, and the next and previous ball in that list.
    list: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
}

impl Lists {
    /// Memory per ball, bytes: its list and its two neighbours in it. The lists' heads are
    /// their owner's to count.
    pub(crate) const BYTES_PER_BALL: u64 = 3 * size_of::<u32>() as u64;

    /// `lists` empty lists for `balls` balls.
    pub fn reset(&mut self, lists: usize, balls: usize) {
        self.head.clear();
        self.head.resize(lists, NONE);
        for per_ball in [&mut self.list, &mut self.next, &mut self.prev] {
            per_ball.clear();
            per_ball.resize(balls, NONE);
        }
    }

    /// Puts `ball`, which is in no list, at the head of list `list`.
    pub(crate) fn insert(&mut self, ball: usize, list: usize) {
        let first = self.head[list];
        self.list[ball] = list as u32;
        self.next[ball] = first;
        self.prev[ball] = NONE;
        if first != NONE {
            self.prev[first as usize] = ball as u32;
        }
        self.head[list] = ball as u32;
    }

    /// Takes `ball` out of its list, if it is in one.
    pub(crate) fn remove(&mut self, ball: usize) {
        let list = self.list[ball];
        if list == NONE {
            return;
        }
        let (next, prev) = (self.next[ball], self.prev[ball]);
        if prev == NONE {
            self.head[list as usize] = next;
        } else {
            self.next[prev as usize] = next;
        }
        if next != NONE {
            self.prev[next as usize] = prev;
        }
        self.list[ball] = NONE;
    }

    /// The list `ball` is in (it must be in one).
    pub(crate) fn list(&self, ball: usize) -> usize {
        debug_assert_ne!(self.list[ball], NONE, "ball {ball} is in no list");
        self.list[ball] as usize
    }

    /// The first ball of list `list`, if it holds any.
    pub(crate) fn first(&self, list: usize) -> Option<usize> {
        let ball = self.head[list];
        (ball != NONE).then_some(ball as usize)
    }

    /// The bytes it holds, for the tests of the memory budget's counts.
    #[cfg(test)]
    pub(crate) fn bytes(&self) -> usize {
        let lengths = [&self.head, &self.list, &self.next, &self.prev].map(Vec::capacity);
        lengths.iter().sum::<usize>() * size_of::<u32>()
    }

    /// The balls in list `list`, most recently put in first.
    pub(crate) fn balls(&self, list: usize) -> impl Iterator<Item = usize> + '_ {
        let mut ball = self.head[list];
        std::iter::from_fn(move || {
            let this = (ball != NONE).then_some(ball as usize)?;
            ball = self.next[this];
            Some(this)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn balls_move_between_lists_and_each_list_lists_its_own() {
        let mut lists = Lists::default();
        lists.reset(2, 4);
        for ball in 0..4 {
            lists.insert(ball, ball % 2);
        }
        lists.remove(2); // the head of list 0: [2, 0] -> [0]
        lists.insert(2, 1);
        lists.remove(3); // the middle of list 1: [2, 3, 1] -> [2, 1]
        lists.remove(3); // in no list: nothing happens
        let contents = [0, 1].map(|list| lists.balls(list).collect::<Vec<_>>());
        assert_eq!(
            contents,
            [vec![0], vec![2, 1]],
            "expected list 0 = [0] and list 1 = [2, 1]"
        );
        assert_eq!(lists.first(1), Some(2), "list 1 starts with ball 2");
    }
}
