//! Binary space-splitting tree over segment boxes (§8.4.3.3, the "quick
//! sort" variant of the octree): each level splits its segments in two equal
//! halves at the median centre along the box's longest axis, down to leaves
//! of a few segments. Build O(N log N), query O(log N + k).

use super::Aabb;
use crate::contact::geometry::V3;

const LEAF: usize = 4;

struct Node {
    bbox: Aabb,
    /// Leaf: range into `order`; inner: children indices.
    first: u32,
    count: u32,
    left: u32,
    right: u32,
}

pub struct Tree {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl Tree {
    pub fn build(boxes: &[Aabb]) -> Tree {
        let mut order: Vec<u32> = (0..boxes.len() as u32)
            .filter(|&i| !boxes[i as usize].is_empty())
            .collect();
        let centre = |i: u32| {
            let b = &boxes[i as usize];
            [0, 1, 2].map(|k| 0.5 * (b.min[k] + b.max[k]))
        };
        let mut nodes = Vec::new();
        if !order.is_empty() {
            let n = order.len();
            build_rec(&mut nodes, &mut order, 0, n, boxes, &centre);
        }
        Tree { nodes, order }
    }

    /// Appends to `out` every segment whose box is within √r2 of p.
    pub fn query(&self, p: V3, r2: f64, boxes: &[Aabb], out: &mut Vec<u32>) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = vec![0u32];
        while let Some(i) = stack.pop() {
            let nd = &self.nodes[i as usize];
            if nd.bbox.dist2(p) > r2 {
                continue;
            }
            if nd.count > 0 {
                for &s in &self.order[nd.first as usize..(nd.first + nd.count) as usize] {
                    if boxes[s as usize].dist2(p) <= r2 {
                        out.push(s);
                    }
                }
            } else {
                stack.push(nd.right);
                stack.push(nd.left);
            }
        }
    }
}

fn build_rec(
    nodes: &mut Vec<Node>,
    order: &mut [u32],
    first: usize,
    count: usize,
    boxes: &[Aabb],
    centre: &dyn Fn(u32) -> V3,
) -> u32 {
    let mut bbox = Aabb::EMPTY;
    for &s in &order[first..first + count] {
        bbox.merge(&boxes[s as usize]);
    }
    let me = nodes.len() as u32;
    nodes.push(Node {
        bbox,
        first: first as u32,
        count: count as u32,
        left: 0,
        right: 0,
    });
    if count <= LEAF {
        return me;
    }
    let ext = [0, 1, 2].map(|k| bbox.max[k] - bbox.min[k]);
    let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
        0
    } else if ext[1] >= ext[2] {
        1
    } else {
        2
    };
    let mid = count / 2;
    let slice = &mut order[first..first + count];
    // Median split; ties broken by segment index so the tree is the same on every run.
    slice.select_nth_unstable_by(mid, |&a, &b| {
        centre(a)[axis].total_cmp(&centre(b)[axis]).then(a.cmp(&b))
    });
    let l = build_rec(nodes, order, first, mid, boxes, centre);
    let r = build_rec(nodes, order, first + mid, count - mid, boxes, centre);
    let nd = &mut nodes[me as usize];
    nd.count = 0;
    nd.left = l;
    nd.right = r;
    me
}
