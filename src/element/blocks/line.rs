//! Trusses (/PROP/TYPE2) and beams (/PROP/TYPE3): one block per kind over
//! its kernel in `crate::element` (`truss`, `beam`). A beam's third node
//! orients it at t = 0 and takes no force.

use super::common::{decode_state, settle_common};
use super::sections::{part_material, per_part};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::beam::{beam_init, beam_nodal_stiffness, beam_step, BeamSection, BeamState};
use crate::element::truss::{
    truss_init, truss_nodal_stiffness, truss_step, TrussSection, TrussState,
};
use crate::element::SLOT;
use crate::material::Material;
use crate::model::{ElementKind, MaterialSpec, Part, Property, PropertyKind, NO_NODE};
use rayon::prelude::*;

/// One line element kernel (truss or beam).
pub trait LineKernel: Send + Sync + 'static {
    type Section: Send + Sync;
    type State: Send + Sync + Clone + serde::Serialize + serde::de::DeserializeOwned;
    const KIND: ElementKind;
    fn section(prop: &Property, m: &Material) -> Result<Self::Section, String>;
    /// State at t = 0 from the two nodes and the orientation node.
    fn init(
        sec: &Self::Section,
        x: &[[f64; 3]; 2],
        x3: Option<[f64; 3]>,
    ) -> Result<Self::State, String>;
    /// Forces and moments on the two nodes, energy increment, time step, failed.
    fn step(
        sec: &Self::Section,
        x: &[[f64; 3]; 2],
        v: &[[f64; 3]; 2],
        w: &[[f64; 3]; 2],
        dt: f64,
        st: &mut Self::State,
    ) -> ([[f64; 6]; 2], f64, bool);
    /// Axial force, plastic strain, internal energy, plastic work.
    fn values(st: &Self::State) -> [f64; 4];
    /// The nodal stiffness (K, K_rot) of each end for /DT/NODA/CST.
    fn nodal(sec: &Self::Section, st: &Self::State, x: &[[f64; 3]; 2]) -> (f64, f64);
}

pub struct Truss;
pub struct Beam;

impl LineKernel for Truss {
    type Section = TrussSection;
    type State = TrussState;
    const KIND: ElementKind = ElementKind::Truss;
    fn section(prop: &Property, m: &Material) -> Result<TrussSection, String> {
        match &prop.card.kind {
            PropertyKind::Truss(t) => TrussSection::new(t.area, t.gap, m)
                .map_err(|e| format!("/PROP/TRUSS/{}: {e}", prop.card.id)),
            _ => Err(format!(
                "/PROP/{}: a truss part needs /PROP/TRUSS (TYPE2)",
                prop.card.id
            )),
        }
    }
    fn init(
        sec: &TrussSection,
        _x: &[[f64; 3]; 2],
        _x3: Option<[f64; 3]>,
    ) -> Result<TrussState, String> {
        Ok(truss_init(sec))
    }
    fn step(
        sec: &TrussSection,
        x: &[[f64; 3]; 2],
        v: &[[f64; 3]; 2],
        _w: &[[f64; 3]; 2],
        dt: f64,
        st: &mut TrussState,
    ) -> ([[f64; 6]; 2], f64, bool) {
        let o = truss_step(sec, x, v, dt, st);
        let f = o.f.map(|a| [a[0], a[1], a[2], 0.0, 0.0, 0.0]);
        (f, o.dt, o.failed)
    }
    fn values(st: &TrussState) -> [f64; 4] {
        [st.sig * st.area, st.eps_p, st.eint, st.eplas]
    }
    fn nodal(sec: &TrussSection, st: &TrussState, x: &[[f64; 3]; 2]) -> (f64, f64) {
        (truss_nodal_stiffness(sec, st, x), 0.0)
    }
}

impl LineKernel for Beam {
    type Section = BeamSection;
    type State = BeamState;
    const KIND: ElementKind = ElementKind::Beam;
    fn section(prop: &Property, m: &Material) -> Result<BeamSection, String> {
        match &prop.card.kind {
            PropertyKind::Beam(b) => {
                BeamSection::new(b, m).map_err(|e| format!("/PROP/BEAM/{}: {e}", prop.card.id))
            }
            _ => Err(format!(
                "/PROP/{}: a beam part needs /PROP/BEAM (TYPE3)",
                prop.card.id
            )),
        }
    }
    fn init(
        sec: &BeamSection,
        x: &[[f64; 3]; 2],
        x3: Option<[f64; 3]>,
    ) -> Result<BeamState, String> {
        // A stubby beam needs the engine's run-time inertia raise (PDLEN3).
        let l = crate::vec3::norm(crate::vec3::sub(x[1], x[0]));
        let p = &sec.p;
        let slender = p.area * l * l / (12.0 * p.iyy.max(p.izz));
        if slender < 1.0 {
            return Err(format!(
                "A·L²/(12·I) = {slender:.3} < 1: a stubby beam (its nodal inertia raised at run time by the reference engine) is not computed yet"
            ));
        }
        Ok(beam_init(x, x3))
    }
    fn step(
        sec: &BeamSection,
        x: &[[f64; 3]; 2],
        v: &[[f64; 3]; 2],
        w: &[[f64; 3]; 2],
        dt: f64,
        st: &mut BeamState,
    ) -> ([[f64; 6]; 2], f64, bool) {
        let o = beam_step(sec, x, v, w, dt, st);
        (o.f, o.dt, o.failed)
    }
    fn values(st: &BeamState) -> [f64; 4] {
        [st.f[0], st.eps_p, st.eint, st.eplas]
    }
    fn nodal(sec: &BeamSection, _st: &BeamState, x: &[[f64; 3]; 2]) -> (f64, f64) {
        beam_nodal_stiffness(sec, x)
    }
}

pub struct LineBlock<K: LineKernel> {
    le: LocalElements,
    sections: Vec<K::Section>,
    section: Vec<u16>,
    state: Vec<K::State>,
    alive: Vec<bool>,
    steps: Vec<ElemStep>,
}

impl<K: LineKernel> LineBlock<K> {
    pub fn new(
        le: LocalElements,
        x: &[[f64; 3]],
        parts: &[Part],
        props: &[Property],
        mats: &[MaterialSpec],
    ) -> Result<Self, String> {
        let (sections, section) = per_part(&le, |p| {
            let part = &parts[p as usize];
            let prop = &props[part.prop.ok_or("line element part without property")? as usize];
            let card = part_material(part, mats, "truss or beam part without material")?;
            K::section(prop, &Material::from_card(card))
        })?;
        let stride = K::KIND.nodes();
        let n = le.global.len();
        let mut state = Vec::with_capacity(n);
        for e in 0..n {
            let nodes = &le.nodes[stride * e..stride * (e + 1)];
            let xe = [x[nodes[0] as usize], x[nodes[1] as usize]];
            let x3 = nodes
                .get(2)
                .filter(|&&k| k != NO_NODE)
                .map(|&k| x[k as usize]);
            let st = K::init(&sections[section[e] as usize], &xe, x3)
                .map_err(|why| format!("{} element {}: {why}", K::KIND.keyword(), le.global[e]))?;
            state.push(st);
        }
        Ok(LineBlock {
            le,
            sections,
            section,
            state,
            alive: vec![true; n],
            steps: vec![ElemStep::default(); n],
        })
    }
}

/// The first two nodes' values of a line element (the beam's third is not loaded).
fn ends(le: &LocalElements, stride: usize, e: usize, a: &[[f64; 3]]) -> [[f64; 3]; 2] {
    [
        a[le.nodes[stride * e] as usize],
        a[le.nodes[stride * e + 1] as usize],
    ]
}

impl<K: LineKernel> Block for LineBlock<K> {
    fn kind(&self) -> ElementKind {
        K::KIND
    }
    fn local(&self) -> &LocalElements {
        &self.le
    }
    fn corners(&self) -> usize {
        2
    }
    fn compute(
        &mut self,
        x: &[[f64; 3]],
        v: &[[f64; 3]],
        vr: &[[f64; 3]],
        dt: f64,
        contrib: &mut [[f64; SLOT]],
    ) {
        let (le, sections, section) = (&self.le, &self.sections, &self.section);
        let stride = K::KIND.nodes();
        contrib
            .par_chunks_mut(2)
            .zip(self.state.par_iter_mut())
            .zip(self.steps.par_iter_mut())
            .zip(self.alive.par_iter())
            .enumerate()
            .for_each(|(e, (((c, st), out), alive))| {
                if !*alive {
                    c.iter_mut().for_each(|s| *s = [0.0; SLOT]);
                    *out = ElemStep {
                        dt: f64::INFINITY,
                        ..Default::default()
                    };
                    return;
                }
                let w = if vr.is_empty() {
                    [[0.0; 3]; 2]
                } else {
                    ends(le, stride, e, vr)
                };
                let (f, edt, failed) = K::step(
                    &sections[section[e] as usize],
                    &ends(le, stride, e, x),
                    &ends(le, stride, e, v),
                    &w,
                    dt,
                    st,
                );
                c[0] = f[0];
                c[1] = f[1];
                *out = ElemStep {
                    dt: edt,
                    failed,
                    bad: false,
                };
            });
    }
    fn steps(&self) -> &[ElemStep] {
        &self.steps
    }
    fn nodal_stiffness(&self, x: &[[f64; 3]], contrib: &mut [[f64; SLOT]]) -> bool {
        let (le, sections, section) = (&self.le, &self.sections, &self.section);
        let stride = K::KIND.nodes();
        contrib
            .par_chunks_mut(2)
            .zip(self.state.par_iter())
            .zip(self.alive.par_iter())
            .enumerate()
            .for_each(|(e, ((c, st), alive))| {
                let (k, kr) = if *alive {
                    K::nodal(&sections[section[e] as usize], st, &ends(le, stride, e, x))
                } else {
                    (0.0, 0.0)
                };
                c.iter_mut().for_each(|s| *s = [k, 0.0, 0.0, kr, 0.0, 0.0]);
            });
        true
    }
    fn settle(&mut self) -> Option<(u32, &'static str)> {
        settle_common(&mut self.alive, &self.steps, &self.le, "")
    }
    fn alive(&self, e: usize) -> bool {
        self.alive[e]
    }
    fn rows(&self) -> Vec<ElemRow> {
        (0..self.le.global.len())
            .map(|e| {
                let [n, ep, eint, _] = K::values(&self.state[e]);
                let deleted = if self.alive[e] { 0.0 } else { 1.0 };
                (self.le.global[e], [n, 0.0, 0.0, ep, 0.0, eint, deleted])
            })
            .collect()
    }
    fn outputs(&self) -> Vec<ElemOut> {
        self.state
            .iter()
            .zip(&self.alive)
            .map(|(s, &alive)| {
                let [n, ep, eint, eplas] = K::values(s);
                ElemOut {
                    von_mises: n.abs(),
                    eps_p: ep,
                    thick: 0.0,
                    eint,
                    ehg: 0.0,
                    eplas,
                    deleted: !alive,
                }
            })
            .collect()
    }
    fn export_state(&self, e: usize) -> Vec<u8> {
        bincode::serialize(&(&self.state[e], self.alive[e])).expect("element state serializes")
    }
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
        let (st, alive): (K::State, bool) = decode_state(bytes, K::KIND.keyword())?;
        self.state[e] = st;
        self.alive[e] = alive;
        Ok(())
    }
}

fn build<K: LineKernel>(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(LineBlock::<K>::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}

/// The registry's builders.
pub(super) fn build_truss(input: BlockInput) -> Result<Box<dyn Block>, String> {
    build::<Truss>(input)
}

pub(super) fn build_beam(input: BlockInput) -> Result<Box<dyn Block>, String> {
    build::<Beam>(input)
}
