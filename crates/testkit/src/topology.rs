//! How the triangles of a mesh or domain meet: the edge counts that tell a
//! watertight, consistently oriented triangulation from one with cracks,
//! overlaps or flipped triangles.

use std::collections::HashMap;

/// How often each directed edge `(from, to)` occurs in `triangles`, each
/// triangle `[a, b, c]` giving `a → b`, `b → c` and `c → a`. In a
/// consistently oriented triangulation every count is 1, and an inner edge
/// also occurs reversed (from its neighbour).
#[must_use]
pub fn directed_edges(triangles: &[[u32; 3]]) -> HashMap<(u32, u32), usize> {
    let mut count = HashMap::new();
    for &[a, b, c] in triangles {
        for edge in [(a, b), (b, c), (c, a)] {
            *count.entry(edge).or_insert(0) += 1;
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_triangles_of_a_quad_share_their_diagonal_reversed() {
        let edges = directed_edges(&[[0, 1, 2], [0, 2, 3]]);
        assert_eq!(edges.len(), 6);
        assert!(edges.values().all(|&n| n == 1));
        assert!(edges.contains_key(&(2, 0)) && edges.contains_key(&(0, 2)));
    }

    #[test]
    fn a_triangle_given_twice_counts_its_edges_twice() {
        let edges = directed_edges(&[[0, 1, 2], [1, 2, 0]]);
        assert_eq!(edges.len(), 3);
        assert!(edges.values().all(|&n| n == 2));
    }
}
