//! Springs: one block per spring property type (/PROP/TYPE4 axial,
//! TYPE8 general, TYPE13 spring beam), each over its kernel in
//! `crate::element` (`spring`, `spring_general`, `spring_beam`).

use super::common::{decode_state, gather, settle_common};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::spring::{AxialSpring, SpringOut, SpringState};
use crate::element::spring_beam::SpringBeam;
use crate::element::spring_general::GeneralSpring;
use crate::element::SLOT;
use crate::model::{ElementKind, Function, Part, Property, PropertyKind};
use rayon::prelude::*;
use std::collections::HashMap;

/// What a spring kernel needs of one element at one step.
pub struct SpringIn<'a> {
    pub x: &'a [[f64; 3]; 2],
    pub v: &'a [[f64; 3]; 2],
    pub vr: &'a [[f64; 3]; 2],
    pub l0: f64,
    pub dt: f64,
    pub masses: [f64; 2],
}

/// One spring property type's kernel.
pub trait SpringKernel: Send + Sync + Sized + 'static {
    /// The kernel of a property, or why it is not computed.
    fn of(prop: &Property, functions: &[Function]) -> Result<Self, String>;
    fn init(x: &[[f64; 3]; 2]) -> SpringState;
    fn step(&self, i: SpringIn, st: &mut SpringState) -> SpringOut;
}

fn wrong_type(prop: &Property) -> String {
    format!("/PROP/{}: not a spring property of this type", prop.card.id)
}

impl SpringKernel for AxialSpring {
    fn of(prop: &Property, functions: &[Function]) -> Result<Self, String> {
        let PropertyKind::Spring(s) = &prop.card.kind else {
            return Err(wrong_type(prop));
        };
        AxialSpring::new(s, functions).map_err(|e| format!("/PROP/SPRING/{}: {e}", prop.card.id))
    }
    fn init(x: &[[f64; 3]; 2]) -> SpringState {
        AxialSpring::init(x)
    }
    fn step(&self, i: SpringIn, st: &mut SpringState) -> SpringOut {
        AxialSpring::step(self, i.x, i.v, i.l0, i.dt, i.masses, st)
    }
}

impl SpringKernel for GeneralSpring {
    fn of(prop: &Property, functions: &[Function]) -> Result<Self, String> {
        let PropertyKind::GeneralSpring(s) = &prop.card.kind else {
            return Err(wrong_type(prop));
        };
        GeneralSpring::new(s, functions)
            .map_err(|e| format!("/PROP/SPR_GENE/{}: {e}", prop.card.id))
    }
    fn init(x: &[[f64; 3]; 2]) -> SpringState {
        GeneralSpring::init(x)
    }
    fn step(&self, i: SpringIn, st: &mut SpringState) -> SpringOut {
        GeneralSpring::step(self, i.x, i.vr, i.dt, st)
    }
}

impl SpringKernel for SpringBeam {
    fn of(prop: &Property, functions: &[Function]) -> Result<Self, String> {
        let PropertyKind::SpringBeam(s) = &prop.card.kind else {
            return Err(wrong_type(prop));
        };
        SpringBeam::new(s, functions).map_err(|e| format!("/PROP/SPR_BEAM/{}: {e}", prop.card.id))
    }
    fn init(x: &[[f64; 3]; 2]) -> SpringState {
        SpringBeam::init(x)
    }
    fn step(&self, i: SpringIn, st: &mut SpringState) -> SpringOut {
        SpringBeam::step(self, i.x, i.v, i.vr, i.l0, i.dt, st)
    }
}

pub struct SpringBlock<K: SpringKernel> {
    le: LocalElements,
    kernels: Vec<K>,
    kernel_of: Vec<u16>,
    l0: Vec<f64>,
    state: Vec<SpringState>,
    alive: Vec<bool>,
    steps: Vec<ElemStep>,
    /// Nodal masses of each spring's two nodes (the step of a massless spring).
    masses: Vec<[f64; 2]>,
}

impl<K: SpringKernel> SpringBlock<K> {
    pub fn new(
        le: LocalElements,
        x: &[[f64; 3]],
        mass: &[f64],
        parts: &[Part],
        props: &[Property],
        functions: &[Function],
    ) -> Result<Self, String> {
        let mut kernels = Vec::new();
        let mut of_part: HashMap<u32, u16> = HashMap::new();
        let mut kernel_of = Vec::new();
        for &p in &le.part {
            let k = match of_part.get(&p) {
                Some(&k) => k,
                None => {
                    let part = &parts[p as usize];
                    let prop = &props[part.prop.ok_or("spring part without property")? as usize];
                    kernels.push(K::of(prop, functions)?);
                    of_part.insert(p, (kernels.len() - 1) as u16);
                    (kernels.len() - 1) as u16
                }
            };
            kernel_of.push(k);
        }
        let n = le.global.len();
        let corners: Vec<[[f64; 3]; 2]> = (0..n).map(|e| gather::<2>(&le, e, x)).collect();
        let l0 = corners
            .iter()
            .map(|a| crate::vec3::norm(crate::vec3::sub(a[1], a[0])))
            .collect();
        let state = corners.iter().map(K::init).collect();
        let masses = (0..n)
            .map(|e| {
                [
                    mass[le.nodes[2 * e] as usize],
                    mass[le.nodes[2 * e + 1] as usize],
                ]
            })
            .collect();
        Ok(SpringBlock {
            le,
            kernels,
            kernel_of,
            l0,
            state,
            alive: vec![true; n],
            steps: vec![ElemStep::default(); n],
            masses,
        })
    }
}

impl<K: SpringKernel> Block for SpringBlock<K> {
    fn kind(&self) -> ElementKind {
        ElementKind::Spring
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
        let (le, kernels, kernel_of, l0, masses) = (
            &self.le,
            &self.kernels,
            &self.kernel_of,
            &self.l0,
            &self.masses,
        );
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
                let (xe, ve) = (gather::<2>(le, e, x), gather::<2>(le, e, v));
                let we = if vr.is_empty() {
                    [[0.0; 3]; 2]
                } else {
                    gather::<2>(le, e, vr)
                };
                let input = SpringIn {
                    x: &xe,
                    v: &ve,
                    vr: &we,
                    l0: l0[e],
                    dt,
                    masses: masses[e],
                };
                let o = kernels[kernel_of[e] as usize].step(input, st);
                c[0] = o.f[0];
                c[1] = o.f[1];
                *out = ElemStep {
                    dt: o.dt,
                    failed: o.failed,
                    bad: false,
                };
            });
    }
    fn steps(&self) -> &[ElemStep] {
        &self.steps
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
                let s = &self.state[e];
                let deleted = if self.alive[e] { 0.0 } else { 1.0 };
                (
                    self.le.global[e],
                    [s.force(), 0.0, 0.0, 0.0, 0.0, s.eint, deleted],
                )
            })
            .collect()
    }
    fn outputs(&self) -> Vec<ElemOut> {
        self.state
            .iter()
            .zip(&self.alive)
            .map(|(s, &alive)| ElemOut {
                von_mises: s.force().abs(),
                eps_p: 0.0,
                thick: 0.0,
                eint: s.eint,
                ehg: 0.0,
                eplas: 0.0,
                deleted: !alive,
            })
            .collect()
    }
    fn export_state(&self, e: usize) -> Vec<u8> {
        bincode::serialize(&(&self.state[e], self.alive[e])).expect("element state serializes")
    }
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
        let (st, alive): (SpringState, bool) = decode_state(bytes, "spring")?;
        self.state[e] = st;
        self.alive[e] = alive;
        Ok(())
    }
}

fn build<K: SpringKernel>(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(SpringBlock::<K>::new(
        input.le,
        input.x,
        input.mass,
        input.parts,
        input.props,
        input.functions,
    )?))
}

/// The registry's builders, one per property type.
pub(super) fn build_axial(input: BlockInput) -> Result<Box<dyn Block>, String> {
    build::<AxialSpring>(input)
}

pub(super) fn build_general(input: BlockInput) -> Result<Box<dyn Block>, String> {
    build::<GeneralSpring>(input)
}

pub(super) fn build_beam(input: BlockInput) -> Result<Box<dyn Block>, String> {
    build::<SpringBeam>(input)
}
