//! Broad phase: which main segments can a secondary node reach?
//!
//! Two sorts of the theory manual, one exact answer: for every query point,
//! the ascending list of segments whose bounding box lies within `reach` of
//! it. `bucket` is the voxel bucket sort of §8.4.3.2 (linear on regular
//! meshes); `tree` is the binary space-splitting quick sort of §8.4.3.3
//! (N log N whatever the mesh). [`choose`] picks one per interface from the
//! size and spread of its segments; both give the same candidates, so the
//! choice never changes a result.
//!
//! Candidate lists are kept while the largest motion since the last sort is
//! below half the sorting margin (Bumult): see `contact::ContactSystem`.

pub mod bucket;
pub mod tree;

use super::geometry::V3;
use rayon::prelude::*;

/// Axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: V3,
    pub max: V3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
    };
    pub fn of_points(p: &[V3]) -> Aabb {
        let mut b = Aabb::EMPTY;
        for q in p {
            b.include(*q);
        }
        b
    }
    pub fn include(&mut self, q: V3) {
        for k in 0..3 {
            self.min[k] = self.min[k].min(q[k]);
            self.max[k] = self.max[k].max(q[k]);
        }
    }
    pub fn merge(&mut self, o: &Aabb) {
        for k in 0..3 {
            self.min[k] = self.min[k].min(o.min[k]);
            self.max[k] = self.max[k].max(o.max[k]);
        }
    }
    pub fn grown(&self, d: f64) -> Aabb {
        Aabb {
            min: [self.min[0] - d, self.min[1] - d, self.min[2] - d],
            max: [self.max[0] + d, self.max[1] + d, self.max[2] + d],
        }
    }
    pub fn is_empty(&self) -> bool {
        (0..3).any(|k| self.min[k] > self.max[k])
    }
    /// The box's centre (NaN-free only for a non-empty box).
    pub fn centre(&self) -> V3 {
        [0, 1, 2].map(|k| 0.5 * (self.min[k] + self.max[k]))
    }
    pub fn diagonal(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = [0, 1, 2].map(|k| self.max[k] - self.min[k]);
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    }
    /// Squared distance from a point to the box (0 inside).
    #[inline]
    pub fn dist2(&self, p: V3) -> f64 {
        let mut s = 0.0;
        for k in 0..3 {
            let d = if p[k] < self.min[k] {
                self.min[k] - p[k]
            } else if p[k] > self.max[k] {
                p[k] - self.max[k]
            } else {
                0.0
            };
            s += d * d;
        }
        s
    }
    pub fn overlaps(&self, o: &Aabb) -> bool {
        (0..3).all(|k| self.min[k] <= o.max[k] && o.min[k] <= self.max[k])
    }
    pub fn contains(&self, p: V3) -> bool {
        (0..3).all(|k| p[k] >= self.min[k] && p[k] <= self.max[k])
    }
}

/// Which sort an interface uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Voxel bucket sort (§8.4.3.2).
    Bucket,
    /// Binary space-splitting tree (§8.4.3.3).
    Tree,
}

/// Bucket sort when the segments are of similar size (largest box diagonal
/// within 4× the mean) and there are enough of them to fill a grid; the tree
/// otherwise, whose cost does not depend on the mesh's regularity.
pub fn choose(boxes: &[Aabb]) -> Method {
    let live: Vec<f64> = boxes
        .iter()
        .filter(|b| !b.is_empty())
        .map(|b| b.diagonal())
        .collect();
    if live.len() < 64 {
        return Method::Tree;
    }
    let mean = live.iter().sum::<f64>() / live.len() as f64;
    let max = live.iter().cloned().fold(0.0, f64::max);
    if max <= 4.0 * mean {
        Method::Bucket
    } else {
        Method::Tree
    }
}

/// Candidates in CSR form: `segs[ptr[i]..ptr[i+1]]` are query `i`'s segments, ascending.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Candidates {
    pub ptr: Vec<usize>,
    pub segs: Vec<u32>,
}

/// For every point, the segments (ascending) whose box is within `reach`.
/// Empty boxes (removed segments) are never candidates.
pub fn candidates(points: &[V3], reach: f64, boxes: &[Aabb], method: Method) -> Candidates {
    let r2 = reach * reach;
    let lists: Vec<Vec<u32>> = match method {
        Method::Tree => {
            let t = tree::Tree::build(boxes);
            points
                .par_iter()
                .map(|&p| {
                    let mut out = Vec::new();
                    t.query(p, r2, boxes, &mut out);
                    out.sort_unstable();
                    out
                })
                .collect()
        }
        Method::Bucket => {
            let g = bucket::Grid::build(boxes, reach);
            points
                .par_iter()
                .map(|&p| {
                    let mut out = Vec::new();
                    g.query(p, r2, boxes, &mut out);
                    out.sort_unstable();
                    out
                })
                .collect()
        }
    };
    let mut ptr = Vec::with_capacity(points.len() + 1);
    ptr.push(0);
    let mut segs = Vec::with_capacity(lists.iter().map(|l| l.len()).sum());
    for l in lists {
        segs.extend_from_slice(&l);
        ptr.push(segs.len());
    }
    Candidates { ptr, segs }
}

/// The reference answer by direct search (N², §8.4.3): for tests.
pub fn brute_force(points: &[V3], reach: f64, boxes: &[Aabb]) -> Candidates {
    let r2 = reach * reach;
    let mut ptr = vec![0];
    let mut segs = Vec::new();
    for &p in points {
        for (s, b) in boxes.iter().enumerate() {
            if !b.is_empty() && b.dist2(p) <= r2 {
                segs.push(s as u32);
            }
        }
        ptr.push(segs.len());
    }
    Candidates { ptr, segs }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pseudo-random irregular cloud of small and large boxes.
    fn cloud(n: usize, seed: u64) -> (Vec<V3>, Vec<Aabb>) {
        let mut s = seed;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64) / ((1u64 << 53) as f64)
        };
        let mut boxes = Vec::new();
        for i in 0..n {
            let c = [rnd() * 10.0, rnd() * 10.0, rnd() * 2.0];
            let h = if i % 17 == 0 { 2.0 } else { 0.1 + 0.2 * rnd() };
            boxes.push(Aabb {
                min: [c[0] - h, c[1] - h, c[2] - 0.01],
                max: [c[0] + h, c[1] + h, c[2] + 0.01],
            });
        }
        let pts = (0..n)
            .map(|_| [rnd() * 10.0, rnd() * 10.0, rnd() * 2.0])
            .collect();
        (pts, boxes)
    }

    #[test]
    fn bucket_and_tree_find_exactly_what_direct_search_finds() {
        for seed in 1..4 {
            let (pts, mut boxes) = cloud(500, seed);
            boxes[7] = Aabb::EMPTY;
            let reach = 0.15;
            let reference = brute_force(&pts, reach, &boxes);
            assert_eq!(candidates(&pts, reach, &boxes, Method::Tree), reference);
            assert_eq!(candidates(&pts, reach, &boxes, Method::Bucket), reference);
            assert!(reference.segs.len() > 100, "the test must find pairs");
        }
    }

    #[test]
    fn choice_follows_the_spread_of_segment_sizes() {
        let regular: Vec<Aabb> = (0..100)
            .map(|i| Aabb {
                min: [i as f64, 0.0, 0.0],
                max: [i as f64 + 1.0, 1.0, 0.0],
            })
            .collect();
        assert_eq!(choose(&regular), Method::Bucket);
        let mut irregular = regular.clone();
        irregular[3].max = [200.0, 50.0, 0.0];
        assert_eq!(choose(&irregular), Method::Tree);
    }
}
