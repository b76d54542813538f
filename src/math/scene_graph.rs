//! Global transforms down a scene graph (notes 01 §6.4): each node's local
//! matrix times its parents' up the chain, computed once per node, so a
//! chain of n nodes costs n products, not n^2 / 2.

use glam::Mat4;

/// `global[i] = global[parent[i]] * local[i]` (a root's is its local).
/// Parents may come before or after their children. A parent index out of
/// range counts as none; a cycle is cut where the walk first meets itself
/// again (the loaders refuse cycles; this keeps an edited graph finite).
pub fn chain_globals(local: &[Mat4], parents: &[Option<usize>]) -> Vec<Mat4> {
    let n = local.len();
    let mut global = vec![Mat4::IDENTITY; n];
    let mut done = vec![false; n];
    let mut path = Vec::new();
    for i in 0..n {
        // Up to the first ancestor already done, or the root.
        let mut at = i;
        while !done[at] && path.len() <= n {
            path.push(at);
            match parents[at] {
                Some(p) if p < n => at = p,
                _ => break,
            }
        }
        // Then down again, each node from its parent's global.
        while let Some(j) = path.pop() {
            global[j] = match parents[j] {
                Some(p) if p < n && done[p] => global[p] * local[j],
                _ => local[j],
            };
            done[j] = true;
        }
    }
    global
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn globals_compose_parents_first_whatever_the_order() {
        let t = |x: f32| Mat4::from_translation(Vec3::new(x, 0.0, 0.0));
        // 2 -> 0 -> 1 (child -> parent), listed out of order.
        let local = [t(1.0), t(10.0), t(100.0), t(1000.0)];
        let parents = [Some(1), None, Some(0), None];
        let g = chain_globals(&local, &parents);
        let x = |m: &Mat4| m.w_axis.x;
        assert_eq!(
            g.iter().map(x).collect::<Vec<_>>(),
            [11.0, 10.0, 111.0, 1000.0]
        );
        // A cycle ends; a long chain is linear (200,000 nodes).
        let g = chain_globals(&local[..2], &[Some(1), Some(0)]);
        assert!(g.iter().all(|m| m.is_finite()));
        let n: usize = 200_000;
        let parents: Vec<Option<usize>> = (0..n).map(|i| i.checked_sub(1)).collect();
        let g = chain_globals(&vec![t(1.0); n], &parents);
        assert_eq!(x(&g[n - 1]), n as f32);
    }
}
