//! What every rank needs to know about the interfaces, built once on rank 0
//! from the model and broadcast: for each interface its passes (secondary
//! nodes against main segments), segment and node stiffness, gaps and sizes,
//! and the global table of contact nodes with the ranks that hold each one.
//!
//! Contact nodes are numbered densely in global node order ("cnode"); every
//! array below speaks in cnodes.

use super::geometry::{self as geo};
use super::interfaces::{
    CandidateSearch, CardCommon, InterfaceType, PassSides, SurfaceSizes, TypeOptions,
};
use super::stiffness;
use crate::model::{geometry as mgeo, Model};
use crate::model::{ElementKind, InterfaceKind};
use std::collections::HashMap;

use super::element_data::{
    bulk, element_volume, face_points, node_elements, shell_size, solid_size, AssembledStiffness,
};
use super::inner_faces::{self, InnerFace};

pub use super::interfaces::layout::{
    closest_segment, ContactSetup, IdelRule, Interface, Pass, NONE,
};

/// What lies under a face: (kind index, element index), shells first.
struct FaceIndex {
    map: HashMap<[u32; 4], (u8, u32)>,
}

fn face_key(f: &[u32]) -> [u32; 4] {
    let mut k = [f[0], f[1], f[2], *f.get(3).unwrap_or(&f[2])];
    k.sort_unstable();
    k
}

/// The faces of an element of `kind` as four local node positions each
/// (triangles repeat their last node): a shell is its one face, a brick its
/// six, a tetrahedron its four; `None` for line elements.
fn element_faces(kind: ElementKind) -> Option<&'static [[usize; 4]]> {
    match kind {
        ElementKind::Shell4 => Some(&[[0, 1, 2, 3]]),
        ElementKind::Shell3 => Some(&[[0, 1, 2, 2]]),
        ElementKind::Brick8 => Some(&mgeo::HEXA_FACES),
        ElementKind::Tetra4 => Some(&[[0, 2, 1, 1], [0, 1, 3, 3], [1, 2, 3, 3], [2, 0, 3, 3]]),
        _ => None,
    }
}

/// Every element a face belongs to (shells by their nodes, solids by each of
/// their faces), in kind then element order: Idel's "elements associated to
/// one segment".
fn face_elements(m: &Model) -> HashMap<[u32; 4], Vec<(u8, u32)>> {
    let mut map: HashMap<[u32; 4], Vec<(u8, u32)>> = HashMap::new();
    for (ki, set) in m.elements.iter().enumerate() {
        let Some(faces) = element_faces(set.kind) else {
            continue;
        };
        for e in 0..set.len() {
            let n = set.nodes_of(e);
            let mut seen: Vec<[u32; 4]> = Vec::new();
            for f in faces {
                let key = face_key(&[n[f[0]], n[f[1]], n[f[2]], n[f[3]]]);
                // A degenerate brick may repeat a face: count the element once.
                if seen.contains(&key) {
                    continue;
                }
                seen.push(key);
                map.entry(key).or_default().push((ki as u8, e as u32));
            }
        }
    }
    map
}

impl FaceIndex {
    fn build(m: &Model) -> FaceIndex {
        let mut map = HashMap::new();
        for (ki, set) in m.elements.iter().enumerate() {
            let Some(faces) = element_faces(set.kind) else {
                continue;
            };
            let shell = matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3);
            for e in 0..set.len() {
                let n = set.nodes_of(e);
                for f in faces {
                    let key = face_key(&[n[f[0]], n[f[1]], n[f[2]], n[f[3]]]);
                    let v = (ki as u8, e as u32);
                    if shell {
                        map.insert(key, v);
                    } else {
                        map.entry(key).or_insert(v);
                    }
                }
            }
        }
        FaceIndex { map }
    }
}

/// Per-node data from the elements touching it: (Ks, g_s, smallest edge):
/// Ks = 0.5·E·t on shells, B·V^(1/3) on solids (card eq. (6), (7)), the largest
/// over the node's elements, or where the type asks for it
/// ([`InterfaceType::assembled_node_stiffness`]) the reference starter's
/// assembled value (`element_data::AssembledStiffness`); g_s = half the
/// largest shell thickness (card comment 11); the smallest edge of the
/// node's elements.
fn node_data(m: &Model, nodes: &[u32], ty: &dyn InterfaceType) -> HashMap<u32, (f64, f64, f64)> {
    let mut out: HashMap<u32, (f64, f64, f64)> = nodes
        .iter()
        .map(|&n| (n, (0.0, 0.0, f64::INFINITY)))
        .collect();
    let mut assembled: HashMap<u32, AssembledStiffness> = if ty.assembled_node_stiffness() {
        nodes.iter().map(|&n| (n, Default::default())).collect()
    } else {
        HashMap::new()
    };
    for (ki, set) in m.elements.iter().enumerate() {
        let shell = matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3);
        let solid = matches!(set.kind, ElementKind::Brick8 | ElementKind::Tetra4);
        if !shell && !solid {
            continue;
        }
        for e in 0..set.len() {
            let n = set.nodes_of(e);
            if !n.iter().any(|q| out.contains_key(q)) {
                continue;
            }
            let part = &m.parts[set.part[e] as usize];
            let Some(mat) = part.mat.map(|i| &m.materials[i as usize]) else {
                continue;
            };
            let (stiff, g) = if shell {
                for (i, q) in n.iter().enumerate() {
                    // A degenerate shell repeats a node: it counts once.
                    if let (false, Some(a)) = (n[..i].contains(q), assembled.get_mut(q)) {
                        a.add_shell(mat.e * set.thick[e]);
                    }
                }
                let size = shell_size(mat, &face_points(m, n), n.len() == 3, set.thick[e]);
                let k = ty.element_stiffness(&size, false);
                (
                    k.unwrap_or_else(|| stiffness::shell(mat.e, set.thick[e])),
                    0.5 * set.thick[e],
                )
            } else {
                let v = element_volume(m, ki, e);
                for q in n {
                    if let Some(a) = assembled.get_mut(q) {
                        a.add_solid(bulk(mat), v.max(0.0) / n.len() as f64);
                    }
                }
                let size = solid_size(mat, v.max(0.0).powf(2.0 / 3.0), v);
                let k = ty.element_stiffness(&size, false);
                (
                    k.unwrap_or_else(|| stiffness::solid_node(bulk(mat), v)),
                    0.0,
                )
            };
            let lmin = (0..n.len())
                .map(|i| {
                    let a = m.nodes.x[n[i] as usize];
                    let b = m.nodes.x[n[(i + 1) % n.len()] as usize];
                    geo::norm(geo::sub(a, b))
                })
                .filter(|&l| l > 0.0)
                .fold(f64::INFINITY, f64::min);
            for q in n {
                if let Some(d) = out.get_mut(q) {
                    d.0 = d.0.max(stiff);
                    d.1 = d.1.max(g);
                    d.2 = d.2.min(lmin);
                }
            }
        }
    }
    for (n, a) in assembled {
        if let Some(d) = out.get_mut(&n) {
            d.0 = a.stiffness();
        }
    }
    out
}

/// Per-segment data from the element under it.
struct SegData {
    k: f64,
    gap: f64,
    thick: Option<f64>,
    elem: (u8, u32),
}

fn segment_data(
    m: &Model,
    faces: &FaceIndex,
    seg: &[u32; 4],
    ty: &dyn InterfaceType,
    owner: Option<(u8, u32)>,
) -> Result<SegData, String> {
    let Some((ki, e)) = owner.or_else(|| faces.map.get(&face_key(seg)).copied()) else {
        return Err(format!(
            "main segment {} {} {} {} is not the face of a shell or solid element: its stiffness is undefined (each main segment must lie on an element)",
            m.nodes.ids[seg[0] as usize], m.nodes.ids[seg[1] as usize], m.nodes.ids[seg[2] as usize], m.nodes.ids[seg[3] as usize]
        ));
    };
    let set = &m.elements[ki as usize];
    let part = &m.parts[set.part[e as usize] as usize];
    let mat = part
        .mat
        .map(|i| &m.materials[i as usize])
        .ok_or_else(|| format!("part {} under a contact segment has no material", part.id))?;
    let xs = face_points(m, seg);
    let tri = seg[3] == seg[2];
    if matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3) {
        let t = set.thick[e as usize];
        let size = shell_size(mat, &xs, tri, t);
        return Ok(SegData {
            k: ty
                .element_stiffness(&size, true)
                .unwrap_or_else(|| stiffness::shell(mat.e, t)),
            gap: 0.5 * t,
            thick: Some(t),
            elem: (ki, e),
        });
    }
    let area = geo::segment_area(&xs, tri);
    let vol = element_volume(m, ki as usize, e as usize);
    let size = solid_size(mat, area, vol);
    let k = ty
        .element_stiffness(&size, true)
        .unwrap_or_else(|| ty.solid_segment_stiffness(bulk(mat), area, vol));
    Ok(SegData {
        k,
        gap: 0.0,
        thick: None,
        elem: (ki, e),
    })
}

/// What every interface's set-up reads: the faces' elements and the
/// contact-node table.
struct Surfaces<'a> {
    faces: FaceIndex,
    /// Every element of each face (empty unless an interface deletes, or
    /// keeps faces between two solids dormant).
    face_elems: HashMap<[u32; 4], Vec<(u8, u32)>>,
    /// Global node index of each cnode, ascending.
    all: &'a [u32],
}

impl Surfaces<'_> {
    fn cn(&self, g: u32) -> u32 {
        self.all.binary_search(&g).expect("contact node") as u32
    }
}

/// Sizes gathered over an interface's passes: main shells, edges and element gaps.
struct Sizes {
    thick_sum: f64,
    thick_min: f64,
    n_shell: usize,
    l_min: f64,
    l_sum: f64,
    n_edges: usize,
    gs_max: f64,
    gm_max: f64,
    /// Edge-to-edge passes: the default Gapmin of their edges (0 otherwise).
    edge_gapmin: f64,
}

/// Builds the contact set-up; `holders[g]` lists the ranks holding global node g.
pub fn build(m: &Model, holders: &[Vec<u32>]) -> Result<ContactSetup, String> {
    // TYPE2 (tied) is a kinematic condition, built by `super::tied`.
    let contact_ifaces = m
        .interfaces
        .iter()
        .filter(|i| !matches!(i.card.kind, InterfaceKind::Type2(_)));
    if contact_ifaces.clone().next().is_none() {
        return Ok(ContactSetup::default());
    }
    let faces = FaceIndex::build(m);
    let any_idel = m.interfaces.iter().any(|i| {
        TypeOptions::from_card(&i.card.kind).is_some_and(|(_, c)| IdelRule::of(c.idel).is_some())
    });
    // Types that keep faces between two solids dormant find them on the same table.
    let any_dormant_faces = m.interfaces.iter().any(|i| {
        TypeOptions::from_card(&i.card.kind)
            .is_some_and(|(t, _)| !t.implementation().inner_solid_faces_as_segments())
    });
    let face_elems = if any_idel || any_dormant_faces {
        face_elements(m)
    } else {
        HashMap::new()
    };
    // Contact nodes.
    let mut all: Vec<u32> = Vec::new();
    for i in contact_ifaces.clone() {
        all.extend(i.secondary_nodes.iter().copied());
        all.extend(i.main_segments.iter().flatten().copied());
        all.extend(i.secondary_segments.iter().flatten().copied());
        all.extend(i.secondary_edges.iter().flatten().copied());
        all.extend(i.main_edges.iter().flatten().copied());
    }
    all.sort_unstable();
    all.dedup();
    let surfaces = Surfaces {
        faces,
        face_elems,
        all: &all,
    };
    let mut interfaces = Vec::new();
    for i in contact_ifaces {
        interfaces.push(build_interface(m, &surfaces, i)?);
    }
    let x0 = all.iter().map(|&g| m.nodes.x[g as usize]).collect();
    let mut holders_ptr = vec![0u32];
    let mut hs = Vec::new();
    for &g in &all {
        hs.extend_from_slice(&holders[g as usize]);
        holders_ptr.push(hs.len() as u32);
    }
    let mass = all.iter().map(|&g| m.nodal_mass[g as usize]).collect();
    Ok(ContactSetup {
        interfaces,
        nodes: all,
        x0,
        holders_ptr,
        holders: hs,
        mass,
    })
}

/// One interface: its type from the registry, its passes, gap rule and sorting margin.
fn build_interface(
    m: &Model,
    surfaces: &Surfaces,
    i: &crate::model::Interface,
) -> Result<Interface, String> {
    let c = &i.card;
    let kw = format!("{}: /INTER/TYPE{}/{}", c.loc, c.type_number(), c.id);
    let Some((mut options, common)) = TypeOptions::from_card(&c.kind) else {
        return Err(format!(
            "{kw}: this interface type is not computed by the engine yet"
        ));
    };
    options.implementation_mut().bind(m, i, &kw)?;
    let ty = options.implementation();
    let mut sizes = Sizes {
        thick_sum: 0.0,
        thick_min: f64::INFINITY,
        n_shell: 0,
        l_min: f64::INFINITY,
        l_sum: 0.0,
        n_edges: 0,
        gs_max: 0.0,
        gm_max: 0.0,
        edge_gapmin: 0.0,
    };
    let mut passes = Vec::new();
    for sides in ty.passes(i) {
        passes.push(if !sides.sec_segs.is_empty() {
            let mut pass = build_pass(m, surfaces, ty, &common, &sides, &mut sizes, &kw)?;
            add_secondary_segments(m, surfaces, ty, &sides, &mut pass, &kw)?;
            sizes.gs_max = sizes
                .gs_max
                .max(pass.sec_gap.iter().fold(0.0, |a, &b| a.max(b)));
            pass
        } else if sides.sec_edges.is_empty() && sides.main_edges.is_empty() {
            build_pass(m, surfaces, ty, &common, &sides, &mut sizes, &kw)?
        } else {
            let cnode = |g: u32| surfaces.cn(g);
            let (pass, e) =
                super::edge_setup::build_edge_pass(m, &cnode, ty, common.idel, &sides, &kw)?;
            sizes.l_sum += e.l_sum;
            sizes.n_edges += e.n_edges;
            sizes.l_min = sizes.l_min.min(e.l_min);
            sizes.gs_max = sizes.gs_max.max(e.gs_max);
            sizes.gm_max = sizes.gm_max.max(e.gm_max);
            sizes.edge_gapmin = e.gapmin;
            pass
        });
    }
    let l_min = if sizes.l_min.is_finite() {
        sizes.l_min
    } else {
        0.0
    };
    let l_mean = if sizes.n_edges > 0 {
        sizes.l_sum / sizes.n_edges as f64
    } else {
        0.0
    };
    let gap_rule = ty.gap_rule(
        &common,
        &SurfaceSizes {
            n_shell: sizes.n_shell,
            thick_sum: sizes.thick_sum,
            thick_min: sizes.thick_min,
            l_min,
            edge_gapmin: sizes.edge_gapmin,
        },
    );
    let max_gap = gap_rule.max_gap(sizes.gs_max, sizes.gm_max);
    if ty.removes_initially_close() {
        let x0: Vec<_> = surfaces
            .all
            .iter()
            .map(|&g| m.nodes.x[g as usize])
            .collect();
        for p in passes
            .iter_mut()
            .filter(|p| !p.is_edge_pass() && !p.is_segment_pass())
        {
            (p.removed_ptr, p.removed) = super::close_neighbours::removal_lists(p, &x0, &gap_rule);
        }
    }
    let margin = (ty.sorting_margin() * l_mean)
        .max(0.1 * max_gap)
        .max(1e-12 * l_mean.max(1.0));
    Ok(Interface {
        id: c.id,
        type_number: c.type_number(),
        title: c.title.clone(),
        options,
        passes,
        gap: gap_rule,
        max_gap,
        margin,
        stfac: common.stfac,
        friction: common.friction,
        tstart: common.tstart,
        tstop: common.tstop,
        ibc: common.ibc,
        inacti: common.inacti,
        idel: common.idel,
    })
}

/// One pass: its main segments' data, its secondary nodes' data, the
/// segments around each main node and the Idel tables.
#[allow(clippy::too_many_arguments)]
fn build_pass(
    m: &Model,
    surfaces: &Surfaces,
    ty: &dyn InterfaceType,
    common: &CardCommon,
    sides: &PassSides,
    sizes: &mut Sizes,
    kw: &str,
) -> Result<Pass, String> {
    let main = sides.main;
    // Faces between two solids: dormant segments of their owner (TYPE25).
    let inner = if ty.inner_solid_faces_as_segments() {
        vec![None; main.len()]
    } else {
        inner_faces::classify(m, &surfaces.face_elems, main, |s| face_key(s))
            .map_err(|e| format!("{kw}: {e}"))?
    };
    let mut segs = Vec::new();
    let mut seg_k = Vec::new();
    let mut seg_gap = Vec::new();
    let mut seg_lmin = Vec::new();
    let mut seg_area = Vec::new();
    let mut seg_elem = Vec::new();
    let mut max_diag = 0.0f64;
    for (s, f) in main.iter().zip(&inner) {
        let owner = f.map(|f| f.owner);
        let d = segment_data(m, &surfaces.faces, s, ty, owner).map_err(|e| format!("{kw}: {e}"))?;
        let x = s.map(|n| m.nodes.x[n as usize]);
        let tri = s[3] == s[2];
        let lm = geo::min_edge(&x, tri);
        let nn = if tri { 3 } else { 4 };
        for e in 0..nn {
            sizes.l_sum += geo::norm(geo::sub(x[(e + 1) % nn], x[e]));
            sizes.n_edges += 1;
        }
        sizes.l_min = sizes.l_min.min(lm);
        if let Some(t) = d.thick {
            sizes.thick_sum += t;
            sizes.thick_min = sizes.thick_min.min(t);
            sizes.n_shell += 1;
        }
        sizes.gm_max = sizes.gm_max.max(d.gap);
        max_diag = max_diag.max(super::search::Aabb::of_points(&x).diagonal());
        segs.push(s.map(|g| surfaces.cn(g)));
        seg_k.push(d.k);
        seg_gap.push(d.gap);
        seg_lmin.push(lm);
        seg_area.push(geo::segment_area(&x, tri));
        seg_elem.push(d.elem);
    }
    let sec = &sides.sec;
    let nd = node_data(m, sec, ty);
    let own_k: HashMap<u32, f64> = match sides.own {
        Some(own) => {
            let mut h: HashMap<u32, f64> = HashMap::new();
            for s in own.iter() {
                let d = segment_data(m, &surfaces.faces, s, ty, None)
                    .map_err(|e| format!("{kw}: {e}"))?;
                for &n in s {
                    let e = h.entry(n).or_insert(0.0);
                    *e = e.max(d.k);
                }
            }
            h
        }
        None => HashMap::new(),
    };
    let mut sec_k = Vec::new();
    let mut sec_gap = Vec::new();
    let mut sec_lmin = Vec::new();
    let border = if ty.zero_gap_on_free_shell_edges() {
        super::element_data::free_shell_edge_nodes(m)
    } else {
        std::collections::HashSet::new()
    };
    for &n in sec {
        let (k, g, l) = nd[&n];
        sec_k.push(own_k.get(&n).copied().unwrap_or(k));
        let g = if border.contains(&n) { 0.0 } else { g };
        sec_gap.push(g);
        sizes.gs_max = sizes.gs_max.max(g);
        sec_lmin.push(if l.is_finite() { l } else { 0.0 });
    }
    let (node_segs_ptr, node_segs_key, node_segs) = segments_around_nodes(&segs);
    let sec_c: Vec<u32> = sec.iter().map(|&n| surfaces.cn(n)).collect();
    let idel = idel_tables(m, surfaces, common.idel, main, &inner, sec);
    let seg_wakers = (0..main.len() as u32)
        .zip(&inner)
        .filter_map(|(i, f)| f.map(|f| (i, f.waker)))
        .collect();
    let mut pass = Pass {
        seg_wakers,
        seg_elems_ptr: idel.0,
        seg_elems: idel.1,
        sec_elems_ptr: idel.2,
        sec_elems: idel.3,
        segs,
        seg_k,
        seg_gap,
        seg_lmin,
        seg_area,
        seg_elem,
        sec: sec_c,
        sec_edges: Vec::new(),
        sec_segs: Vec::new(),
        self_contact: false,
        sec_k,
        sec_gap,
        sec_lmin,
        sec_start_seg: Vec::new(),
        node_segs_ptr,
        node_segs_key,
        node_segs,
        max_diag,
        removed_ptr: Vec::new(),
        removed: Vec::new(),
    };
    if ty.search() == CandidateSearch::Walk {
        pass.sec_start_seg = starter_closest_segments(m, surfaces.all, &pass);
    }
    Ok(pass)
}

/// A segment-to-segment pass's secondary side: its segments as cnodes,
/// each with its element's data as a main segment has it (`sec_k`,
/// `sec_gap`, `sec_lmin` by segment), the largest diagonal among them too.
fn add_secondary_segments(
    m: &Model,
    surfaces: &Surfaces,
    ty: &dyn InterfaceType,
    sides: &PassSides,
    pass: &mut Pass,
    kw: &str,
) -> Result<(), String> {
    pass.self_contact = sides.self_contact;
    for s in sides.sec_segs.iter() {
        let d = segment_data(m, &surfaces.faces, s, ty, None).map_err(|e| format!("{kw}: {e}"))?;
        let x = s.map(|n| m.nodes.x[n as usize]);
        pass.sec_segs.push(s.map(|g| surfaces.cn(g)));
        pass.sec_k.push(d.k);
        pass.sec_gap.push(d.gap);
        pass.sec_lmin.push(geo::min_edge(&x, s[3] == s[2]));
        pass.max_diag = pass
            .max_diag
            .max(super::search::Aabb::of_points(&x).diagonal());
    }
    Ok(())
}

/// The segments around each main node, CSR over the nodes of `segs`
/// ascending: (ptr, node, segments).
fn segments_around_nodes(segs: &[[u32; 4]]) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for (si, s) in segs.iter().enumerate() {
        let mut u = s.to_vec();
        u.sort_unstable();
        u.dedup();
        for n in u {
            pairs.push((n, si as u32));
        }
    }
    pairs.sort_unstable();
    let mut node_segs_key = Vec::new();
    let mut node_segs_ptr = vec![0u32];
    let mut node_segs = Vec::new();
    for (n, s) in pairs {
        if node_segs_key.last() != Some(&n) {
            if !node_segs_key.is_empty() {
                node_segs_ptr.push(node_segs.len() as u32);
            }
            node_segs_key.push(n);
        }
        node_segs.push(s);
    }
    node_segs_ptr.push(node_segs.len() as u32);
    (node_segs_ptr, node_segs_key, node_segs)
}

/// Idel's tables of one pass (empty when the interface does not delete):
/// the elements of each main segment, and with Idel = 1, 2 those of each
/// secondary node, as (segment ptr, segment elements, node ptr, node elements).
type IdelTables = (Vec<u32>, Vec<(u8, u32)>, Vec<u32>, Vec<(u8, u32)>);

fn idel_tables(
    m: &Model,
    surfaces: &Surfaces,
    idel: i64,
    main: &[[u32; 4]],
    inner: &[Option<InnerFace>],
    sec: &[u32],
) -> IdelTables {
    let mut seg_elems_ptr = Vec::new();
    let mut seg_elems = Vec::new();
    let mut sec_elems_ptr = Vec::new();
    let mut sec_elems = Vec::new();
    if let Some(rule) = IdelRule::of(idel) {
        seg_elems_ptr.push(0);
        for (s, f) in main.iter().zip(inner) {
            // An inner face is its owner's only: it leaves with it.
            if let Some(f) = f {
                seg_elems.push(f.owner);
            } else if let Some(v) = surfaces.face_elems.get(&face_key(s)) {
                seg_elems.extend_from_slice(v);
            }
            seg_elems_ptr.push(seg_elems.len() as u32);
        }
        if rule.nodes {
            let ne = node_elements(m, sec);
            sec_elems_ptr.push(0);
            for n in sec {
                sec_elems.extend_from_slice(&ne[n]);
                sec_elems_ptr.push(sec_elems.len() as u32);
            }
        }
    }
    (seg_elems_ptr, seg_elems, sec_elems_ptr, sec_elems)
}

/// The Starter's TYPE5 search (§8.6.6.1): for each secondary node the closest
/// main node over the whole surface, then the closest of the segments around it.
/// Its cost is (secondary nodes) × (main nodes), as the manual says.
fn starter_closest_segments(m: &Model, cnodes: &[u32], pass: &Pass) -> Vec<u32> {
    let xg = |c: u32| m.nodes.x[cnodes[c as usize] as usize];
    pass.sec
        .iter()
        .map(|&s| {
            let p = xg(s);
            let mut best: Option<(f64, u32)> = None;
            for &mn in &pass.node_segs_key {
                if mn == s {
                    continue;
                }
                let d = geo::norm(geo::sub(xg(mn), p));
                if best.is_none_or(|b| d < b.0) {
                    best = Some((d, mn));
                }
            }
            let Some((_, mn)) = best else { return NONE };
            closest_segment(pass.segments_around(mn), p, |seg| {
                Some(pass.segs[seg as usize].map(xg))
            })
            .unwrap_or(NONE)
        })
        .collect()
}
