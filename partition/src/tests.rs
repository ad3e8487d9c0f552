//! Tests of the public API on small hand-checkable meshes.

use crate::test_mesh::quad_grid;
use crate::*;

struct Grid {
    n_nodes: usize,
    ptr: Vec<usize>,
    nodes: Vec<u32>,
}

impl Grid {
    fn new(nx: usize, ny: usize) -> Grid {
        let (n_nodes, ptr, nodes) = quad_grid(nx, ny);
        Grid {
            n_nodes,
            ptr,
            nodes,
        }
    }
    fn mesh(&self) -> Mesh<'_> {
        Mesh {
            n_nodes: self.n_nodes,
            elem_ptr: &self.ptr,
            elem_nodes: &self.nodes,
        }
    }
}

/// Ranks touching every node, computed the slow obvious way.
fn ranks_per_node(mesh: &Mesh, part: &[u32]) -> Vec<Vec<u32>> {
    let mut on = vec![Vec::new(); mesh.n_nodes];
    for (e, &p) in part.iter().enumerate() {
        for &n in mesh.nodes(e) {
            if !on[n as usize].contains(&p) {
                on[n as usize].push(p);
            }
        }
    }
    on
}

fn check_partition(mesh: &Mesh, weights: &[i32], nparts: usize, adjacency: Adjacency) -> Report {
    let mut opts = Options::new(nparts);
    opts.adjacency = adjacency;
    let p = partition(mesh, weights, &opts).unwrap();
    assert_eq!(p.nparts, nparts);
    assert_eq!(p.part.len(), mesh.n_elems());
    assert!(p.part.iter().all(|&r| (r as usize) < nparts));

    // Deterministic across calls.
    let again = partition(mesh, weights, &opts).unwrap();
    assert_eq!(p, again);

    let rep = report(mesh, weights, &p).unwrap();
    assert_eq!(rep.per_rank.len(), nparts);
    let n_elems: usize = rep.per_rank.iter().map(|r| r.elements).sum();
    assert_eq!(n_elems, mesh.n_elems());
    let total: i64 = weights.iter().map(|&w| i64::from(w)).sum();
    assert_eq!(rep.per_rank.iter().map(|r| r.weight).sum::<i64>(), total);
    assert!(rep.per_rank.iter().all(|r| r.elements > 0));
    assert!(
        rep.imbalance <= 0.05,
        "imbalance {} with {nparts} parts: {:?}",
        rep.imbalance,
        rep.per_rank
    );
    let max = rep.per_rank.iter().map(|r| r.weight).max().unwrap();
    let expected = max as f64 * nparts as f64 / total as f64 - 1.0;
    assert!((rep.imbalance - expected).abs() < 1e-12);

    // Node counts against the obvious computation: a node on ranks a and b
    // counts on both, and Σ nodes = n_nodes + Σ (ranks on node − 1).
    let on = ranks_per_node(mesh, &p.part);
    for (r, rr) in rep.per_rank.iter().enumerate() {
        let r = r as u32;
        assert_eq!(rr.nodes, on.iter().filter(|s| s.contains(&r)).count());
        let shared = on.iter().filter(|s| s.contains(&r) && s.len() > 1).count();
        assert_eq!(rr.shared_nodes, shared);
        assert!(rr.shared_nodes > 0 && rr.shared_nodes < rr.nodes);
    }
    let sum_nodes: usize = rep.per_rank.iter().map(|r| r.nodes).sum();
    let extra: usize = on.iter().map(|s| s.len() - 1).sum();
    assert_eq!(sum_nodes, mesh.n_nodes + extra);
    assert!(rep.edge_cut > 0);
    rep
}

#[test]
fn grid_10x14_in_2_and_4_parts() {
    let g = Grid::new(10, 14);
    let mesh = g.mesh();
    let w = vec![element_cost(ElementKind::Shell4, 5); 140];

    let rep2 = check_partition(&mesh, &w, 2, Adjacency::SharedNode);
    // Two ranks: the shared nodes are the same set, seen from both sides; a
    // straight cut across the short side shares 11 nodes, METIS must be close.
    assert_eq!(rep2.per_rank[0].shared_nodes, rep2.per_rank[1].shared_nodes);
    assert!(rep2.per_rank[0].shared_nodes <= 16, "{rep2:?}");

    let rep4 = check_partition(&mesh, &w, 4, Adjacency::SharedNode);
    let shared4: usize = rep4.per_rank.iter().map(|r| r.shared_nodes).sum();
    assert!(shared4 <= 4 * 20, "{rep4:?}");

    check_partition(&mesh, &w, 4, Adjacency::SharedFace);
}

#[test]
fn grid_with_uneven_weights_stays_balanced() {
    // Shell3/shell4 mix, 3 and 5 points, contact on the first three rows.
    let g = Grid::new(10, 14);
    let mesh = g.mesh();
    let elems: Vec<(ElementKind, u32)> = (0..140)
        .map(|e| {
            let kind = if e % 7 == 0 {
                ElementKind::Shell3
            } else {
                ElementKind::Shell4
            };
            (kind, if e % 3 == 0 { 3 } else { 5 })
        })
        .collect();
    let contact: Vec<usize> = (0..30).collect();
    let w = element_weights(&elems, &contact, DEFAULT_CONTACT_EXTRA).unwrap();
    assert_eq!(
        w[0],
        element_cost(ElementKind::Shell3, 3) + DEFAULT_CONTACT_EXTRA
    );
    for nparts in [2, 3, 4, 7] {
        check_partition(&mesh, &w, nparts, Adjacency::SharedNode);
    }
}

#[test]
fn one_part_puts_everything_on_rank_0() {
    let g = Grid::new(3, 2);
    let p = partition(&g.mesh(), &[1; 6], &Options::new(1)).unwrap();
    assert_eq!(p.nparts, 1);
    assert_eq!(p.part, vec![0; 6]);
    let rep = report(&g.mesh(), &[1; 6], &p).unwrap();
    assert_eq!(rep.per_rank[0].nodes, 12);
    assert_eq!(rep.per_rank[0].shared_nodes, 0);
    assert_eq!(rep.edge_cut, 0);
    assert_eq!(rep.imbalance, 0.0);
}

#[test]
fn every_rank_gets_an_element() {
    // As many parts as elements, connected strip and disconnected elements.
    let g = Grid::new(5, 1);
    let p = partition(&g.mesh(), &[1; 5], &Options::new(5)).unwrap();
    let mut seen = p.part.clone();
    seen.sort_unstable();
    assert_eq!(seen, vec![0, 1, 2, 3, 4]);

    let ptr = [0, 2, 4, 6, 8];
    let nodes = [0, 1, 2, 3, 4, 5, 6, 7];
    let mesh = Mesh {
        n_nodes: 8,
        elem_ptr: &ptr,
        elem_nodes: &nodes,
    };
    let p = partition(&mesh, &[3, 1, 1, 1], &Options::new(3)).unwrap();
    let rep = report(&mesh, &[3, 1, 1, 1], &p).unwrap();
    assert!(rep.per_rank.iter().all(|r| r.elements > 0));
    assert_eq!(rep.edge_cut, 0);
    assert!(rep.per_rank.iter().all(|r| r.shared_nodes == 0));
}

#[test]
fn dual_graph_of_a_2x2_grid() {
    // Elements 0 1 / 2 3 (0 at the origin): all share the centre node 4.
    let g = Grid::new(2, 2);
    let node = DualGraph::build(&g.mesh(), Adjacency::SharedNode).unwrap();
    let lists: Vec<Vec<u32>> = (0..4).map(|e| node.neighbours(e).to_vec()).collect();
    assert_eq!(
        lists,
        vec![vec![1, 2, 3], vec![0, 2, 3], vec![0, 1, 3], vec![0, 1, 2]]
    );
    assert_eq!(node.n_edges(), 6);

    let face = DualGraph::build(&g.mesh(), Adjacency::SharedFace).unwrap();
    let lists: Vec<Vec<u32>> = (0..4).map(|e| face.neighbours(e).to_vec()).collect();
    assert_eq!(lists, vec![vec![1, 2], vec![0, 3], vec![0, 3], vec![1, 2]]);
    assert_eq!(face.n_edges(), 4);
    assert_eq!(face.xadj(), &[0, 2, 4, 6, 8]);

    let common2 = DualGraph::build(&g.mesh(), Adjacency::CommonNodes(2)).unwrap();
    assert_eq!(common2, face);
}

#[test]
fn dual_graph_mixed_elements() {
    // 0: quad 0-1-4-3; 1: degenerate quad (triangle) 1-2-4-4; 2: beam 4-5;
    // 3: brick on top of nothing sharing node 0 only; 4: brick sharing the
    // face 10-11-12-13 with brick 3.
    let ptr = [0, 4, 8, 10, 18, 26];
    let nodes = [
        0, 1, 4, 3, //
        1, 2, 4, 4, //
        4, 5, //
        0, 6, 7, 8, 10, 11, 12, 13, //
        10, 11, 12, 13, 14, 15, 16, 17,
    ];
    let mesh = Mesh {
        n_nodes: 18,
        elem_ptr: &ptr,
        elem_nodes: &nodes,
    };
    let face = DualGraph::build(&mesh, Adjacency::SharedFace).unwrap();
    // quad–triangle share edge 1-4; beam joins both shells through node 4;
    // brick 3 touches the quad at one node only (not a face); bricks 3–4
    // share a face.
    assert_eq!(face.neighbours(0), &[1, 2]);
    assert_eq!(face.neighbours(1), &[0, 2]);
    assert_eq!(face.neighbours(2), &[0, 1]);
    assert_eq!(face.neighbours(3), &[4]);
    assert_eq!(face.neighbours(4), &[3]);
    let node = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
    assert_eq!(node.neighbours(0), &[1, 2, 3]);
    assert_eq!(node.neighbours(3), &[0, 4]);
}

#[test]
fn element_costs() {
    use ElementKind::*;
    assert_eq!(element_cost(Shell4, 5), 20);
    assert_eq!(element_cost(Shell4, 0), element_cost(Shell4, 1));
    assert_eq!(element_cost(Shell3, 5), 14);
    assert_eq!(element_cost(Brick8, 1), 16);
    assert_eq!(element_cost(Tetra4, 1), 8);
    for k in [Spring, Truss, Beam] {
        assert!((2..=4).contains(&element_cost(k, 1)));
    }
    assert!(element_cost(Shell4, u32::MAX) > 0);

    let mut w = vec![10, 10, 10];
    add_contact_weight(&mut w, &[2, 0, 2], 5).unwrap();
    assert_eq!(w, vec![15, 10, 20]);
    assert_eq!(
        add_contact_weight(&mut w, &[3], 5),
        Err(PartitionError::ElementOutOfRange {
            element: 3,
            n_elems: 3
        })
    );
    assert!(add_contact_weight(&mut w, &[0], -1).is_err());
    assert!(add_contact_weight(&mut w, &[1, 1], i32::MAX).is_err());
    assert_eq!(w, vec![15, 10, 20], "failed calls leave weights unchanged");
}

#[test]
fn bad_input_is_an_error() {
    let g = Grid::new(2, 2);
    let mesh = g.mesh();
    let ok = [1; 4];
    let opts = |n| Options::new(n);

    let empty = Mesh {
        n_nodes: 0,
        elem_ptr: &[],
        elem_nodes: &[],
    };
    assert_eq!(
        partition(&empty, &[], &opts(1)),
        Err(PartitionError::EmptyMesh)
    );
    let only_zero = Mesh {
        n_nodes: 0,
        elem_ptr: &[0],
        elem_nodes: &[],
    };
    assert_eq!(
        partition(&only_zero, &[], &opts(2)),
        Err(PartitionError::EmptyMesh)
    );
    assert_eq!(
        partition(&mesh, &ok, &opts(0)),
        Err(PartitionError::ZeroParts)
    );
    assert_eq!(
        partition(&mesh, &ok, &opts(5)),
        Err(PartitionError::TooManyParts {
            nparts: 5,
            n_elems: 4
        })
    );
    assert_eq!(
        partition(&mesh, &[1; 3], &opts(2)),
        Err(PartitionError::WeightCount {
            expected: 4,
            got: 3
        })
    );
    assert!(matches!(
        partition(&mesh, &[1, -1, 1, 1], &opts(2)),
        Err(PartitionError::NegativeWeight { element: 1, .. })
    ));
    assert_eq!(
        partition(&mesh, &[0; 4], &opts(2)),
        Err(PartitionError::ZeroTotalWeight)
    );
    assert!(matches!(
        partition(&mesh, &[i32::MAX, 1, 1, 1], &opts(2)),
        Err(PartitionError::TooLarge(_))
    ));
    let mut bad = opts(2);
    bad.ufactor = 0;
    assert!(matches!(
        partition(&mesh, &ok, &bad),
        Err(PartitionError::InvalidOption(_))
    ));
    let mut bad = opts(2);
    bad.max_imbalance = f64::NAN;
    assert!(partition(&mesh, &ok, &bad).is_err());

    // Broken connectivity.
    let out_of_range = Mesh { n_nodes: 8, ..mesh };
    assert!(matches!(
        partition(&out_of_range, &ok, &opts(2)),
        Err(PartitionError::NodeOutOfRange { node: 8, .. })
    ));
    let bad_ptrs: [&[usize]; 3] = [&[1, 4, 8, 12, 16], &[0, 4, 3, 12, 16], &[0, 4, 8, 12, 15]];
    for ptr in bad_ptrs {
        let m = Mesh {
            elem_ptr: ptr,
            ..mesh
        };
        assert!(matches!(
            partition(&m, &ok, &opts(2)),
            Err(PartitionError::InvalidMesh(_))
        ));
        assert!(DualGraph::build(&m, Adjacency::SharedNode).is_err());
    }
    let no_nodes = Mesh {
        elem_ptr: &[0, 4, 4, 12, 16],
        elem_nodes: &g.nodes[..16],
        ..mesh
    };
    assert_eq!(
        partition(&no_nodes, &ok, &opts(2)),
        Err(PartitionError::ElementWithoutNodes { element: 1 })
    );

    // Report on a partition that does not fit the mesh.
    let short = Partition {
        nparts: 2,
        part: vec![0, 1, 0],
    };
    assert!(matches!(
        report(&mesh, &ok, &short),
        Err(PartitionError::PartitionMismatch(_))
    ));
    let bad_rank = Partition {
        nparts: 2,
        part: vec![0, 1, 2, 0],
    };
    assert!(matches!(
        report(&mesh, &ok, &bad_rank),
        Err(PartitionError::PartitionMismatch(_))
    ));
    assert!(report(
        &mesh,
        &[1; 5],
        &Partition {
            nparts: 1,
            part: vec![0; 4]
        }
    )
    .is_err());

    // Every error says something.
    let e = partition(&mesh, &ok, &opts(5)).unwrap_err();
    assert!(e.to_string().contains("5 parts"), "{e}");
    let _: &dyn std::error::Error = &e;
}

#[test]
fn report_serializes() {
    let g = Grid::new(4, 4);
    let mesh = g.mesh();
    let p = partition(&mesh, &[1; 16], &Options::new(2)).unwrap();
    let rep = report(&mesh, &[1; 16], &p).unwrap();
    let json = serde_json::to_string(&rep).unwrap();
    assert!(json.contains("\"shared_nodes\""));
    let back: Report = serde_json::from_str(&json).unwrap();
    assert_eq!(back, rep);
    let opts: Options =
        serde_json::from_str(&serde_json::to_string(&Options::new(4)).unwrap()).unwrap();
    assert_eq!(opts, Options::new(4));
}
