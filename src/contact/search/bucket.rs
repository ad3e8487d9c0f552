//! Voxel bucket sort (§8.4.3.2): space is cut into equal boxes; every segment
//! is listed in each box its bounding box (grown by the reach) overlaps, so a
//! node only looks in its own box. As the manual describes, boxes are first
//! counted and then filled (CSR), so memory follows the occupied boxes.

use super::Aabb;
use crate::contact::geometry::V3;

pub struct Grid {
    origin: V3,
    h: f64,
    dims: [usize; 3],
    ptr: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    pub fn build(boxes: &[Aabb], reach: f64) -> Grid {
        let mut all = Aabb::EMPTY;
        let mut diag_sum = 0.0;
        let mut live = 0usize;
        for b in boxes.iter().filter(|b| !b.is_empty()) {
            all.merge(b);
            diag_sum += b.diagonal();
            live += 1;
        }
        if live == 0 {
            return Grid {
                origin: [0.0; 3],
                h: 1.0,
                dims: [1, 1, 1],
                ptr: vec![0, 0],
                items: Vec::new(),
            };
        }
        let all = all.grown(reach);
        let ext = [0, 1, 2].map(|k| (all.max[k] - all.min[k]).max(0.0));
        // Box size about a segment plus the reach; never more boxes than ~4 per segment.
        let mut h = (diag_sum / live as f64 + 2.0 * reach).max(1e-300);
        let cells = |h: f64| ext.map(|e| ((e / h).floor() as usize + 1).max(1));
        while cells(h).iter().product::<usize>() > 4 * live + 64 {
            h *= 1.26;
        }
        let dims = cells(h);
        let origin = all.min;
        let ncell = dims[0] * dims[1] * dims[2];
        let range = |b: &Aabb| {
            let g = b.grown(reach);
            let lo = [0, 1, 2]
                .map(|k| (((g.min[k] - origin[k]) / h).floor().max(0.0) as usize).min(dims[k] - 1));
            let hi = [0, 1, 2]
                .map(|k| (((g.max[k] - origin[k]) / h).floor().max(0.0) as usize).min(dims[k] - 1));
            (lo, hi)
        };
        let mut count = vec![0u32; ncell + 1];
        for b in boxes.iter().filter(|b| !b.is_empty()) {
            let (lo, hi) = range(b);
            for i in lo[0]..=hi[0] {
                for j in lo[1]..=hi[1] {
                    for k in lo[2]..=hi[2] {
                        count[(k * dims[1] + j) * dims[0] + i + 1] += 1;
                    }
                }
            }
        }
        for c in 1..=ncell {
            count[c] += count[c - 1];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[ncell] as usize];
        for (s, b) in boxes.iter().enumerate() {
            if b.is_empty() {
                continue;
            }
            let (lo, hi) = range(b);
            for i in lo[0]..=hi[0] {
                for j in lo[1]..=hi[1] {
                    for k in lo[2]..=hi[2] {
                        let c = (k * dims[1] + j) * dims[0] + i;
                        items[fill[c] as usize] = s as u32;
                        fill[c] += 1;
                    }
                }
            }
        }
        Grid {
            origin,
            h,
            dims,
            ptr: count,
            items,
        }
    }

    /// Appends to `out` every segment whose box is within √r2 of p.
    pub fn query(&self, p: V3, r2: f64, boxes: &[Aabb], out: &mut Vec<u32>) {
        let mut c = [0usize; 3];
        for k in 0..3 {
            let f = (p[k] - self.origin[k]) / self.h;
            if !(f >= 0.0) || f >= self.dims[k] as f64 {
                return; // outside every grown box
            }
            c[k] = f as usize;
        }
        let cell = (c[2] * self.dims[1] + c[1]) * self.dims[0] + c[0];
        for &s in &self.items[self.ptr[cell] as usize..self.ptr[cell + 1] as usize] {
            if boxes[s as usize].dist2(p) <= r2 {
                out.push(s);
            }
        }
    }
}
