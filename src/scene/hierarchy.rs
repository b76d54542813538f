//! The scene graph of `[[objects]]` (notes 01 §6.4): each object's model
//! matrix is its parent's times its own local transform. The objects are
//! put in an order where every parent comes before its children once
//! (Kahn's topological sort), so a chain of any length is walked in linear
//! time, and a cycle is found in the same walk.

use super::Object;

/// The objects' indices, each parent before its children; `Err(i)` names
/// an object on a cycle. `parents[i]` is object i's parent (an index out
/// of range counts as none).
pub fn parents_first(parents: &[Option<usize>]) -> Result<Vec<usize>, usize> {
    let n = parents.len();
    let parent = |i: usize| parents[i].filter(|&p| p < n);
    // Children as one flat list, grouped by parent (counting sort).
    let mut start = vec![0usize; n + 1];
    for i in 0..n {
        if let Some(p) = parent(i) {
            start[p + 1] += 1;
        }
    }
    for p in 0..n {
        start[p + 1] += start[p];
    }
    let mut fill = start.clone();
    let mut children = vec![0usize; start[n]];
    for i in 0..n {
        if let Some(p) = parent(i) {
            children[fill[p]] = i;
            fill[p] += 1;
        }
    }
    let mut order: Vec<usize> = (0..n).filter(|&i| parent(i).is_none()).collect();
    let mut next = 0;
    while next < order.len() {
        let p = order[next];
        order.extend_from_slice(&children[start[p]..start[p + 1]]);
        next += 1;
    }
    if order.len() < n {
        // Whatever was never reached hangs from a cycle: find one on it.
        let mut reached = vec![false; n];
        order.iter().for_each(|&i| reached[i] = true);
        let mut i = (0..n).find(|&i| !reached[i]).expect("one is left");
        // Walking up n steps from any unreached object lands on the cycle.
        for _ in 0..n {
            i = parent(i).expect("an unreached object has a parent");
        }
        return Err(i);
    }
    Ok(order)
}

/// Every object's model matrix: its local transform, then its parents' up
/// the chain (notes 01 §6.4, scene graphs), parents first. The loader
/// refuses cycles; an object on one (after an edit) keeps its local
/// transform.
pub fn update_models(objects: &mut [Object]) {
    let parents: Vec<Option<usize>> = objects.iter().map(|o| o.parent).collect();
    let n = objects.len();
    let order = parents_first(&parents).unwrap_or_else(|_| (0..n).collect());
    let mut done = vec![false; n];
    for i in order {
        let local = objects[i].local();
        objects[i].model = match parents[i].filter(|&p| p < n && done[p]) {
            Some(p) => objects[p].model * local,
            None => local,
        };
        done[i] = true;
    }
}

#[cfg(test)]
mod tests {
    use super::parents_first;

    #[test]
    fn parents_come_first_and_cycles_are_found() {
        // 3 -> 1 -> 0, 2 -> 0, 4 alone.
        let parents = [None, Some(0), Some(0), Some(1), None];
        let order = parents_first(&parents).unwrap();
        let at = |i: usize| order.iter().position(|&x| x == i).unwrap();
        assert_eq!(order.len(), 5);
        for (i, p) in parents.iter().enumerate() {
            if let Some(p) = p {
                assert!(at(*p) < at(i), "{p} before {i} in {order:?}");
            }
        }
        // 1 -> 2 -> 3 -> 1, and 0 hanging from it.
        let cyclic = [Some(1), Some(2), Some(3), Some(1)];
        let on = parents_first(&cyclic).unwrap_err();
        assert!([1, 2, 3].contains(&on), "{on}");
        // A chain of a million, in linear time.
        let chain: Vec<Option<usize>> = (0..1_000_000)
            .map(|i| if i == 0 { None } else { Some(i - 1) })
            .collect();
        assert_eq!(parents_first(&chain).unwrap()[999_999], 999_999);
    }
}
