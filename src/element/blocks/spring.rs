//! Axial springs (Radioss /PROP/TYPE4; kernel in `crate::element::spring`).

use super::common::{decode_state, gather, settle_common};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::spring::{self, SpringState};
use crate::element::SLOT;
use crate::model::{ElementKind, Function, PropertyKind, SpringProperty};
use crate::model::{Part, Property};
use rayon::prelude::*;
use std::collections::HashMap;

pub struct SpringBlock {
    le: LocalElements,
    props: Vec<SpringProperty>,
    fcts: Vec<Option<Function>>,
    prop_of: Vec<u16>,
    l0: Vec<f64>,
    state: Vec<SpringState>,
    alive: Vec<bool>,
    steps: Vec<ElemStep>,
    /// Nodal masses of each spring's two nodes, for its time step.
    masses: Vec<[f64; 2]>,
}

impl SpringBlock {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        le: LocalElements,
        x: &[[f64; 3]],
        mass: &[f64],
        parts: &[Part],
        props: &[Property],
        functions: &[Function],
    ) -> Result<Self, String> {
        let mut sp = Vec::new();
        let mut fcts = Vec::new();
        let mut of_part: HashMap<u32, u16> = HashMap::new();
        let mut prop_of = Vec::new();
        for &p in &le.part {
            let s = match of_part.get(&p) {
                Some(&s) => s,
                None => {
                    let part = &parts[p as usize];
                    let prop = &props[part.prop.ok_or("spring part without property")? as usize];
                    let PropertyKind::Spring(s) = &prop.card.kind else {
                        return Err(format!(
                            "/PROP/{}: only /PROP/TYPE4 springs are computed by the engine yet",
                            prop.card.id
                        ));
                    };
                    let f1 = if s.fct_id1 == 0 {
                        None
                    } else {
                        functions.iter().find(|f| f.id == s.fct_id1).cloned()
                    };
                    spring::spring_check(s, f1.as_ref())
                        .map_err(|e| format!("/PROP/SPRING/{}: {e}", prop.card.id))?;
                    sp.push(s.clone());
                    fcts.push(f1);
                    of_part.insert(p, (sp.len() - 1) as u16);
                    (sp.len() - 1) as u16
                }
            };
            prop_of.push(s);
        }
        let n = le.global.len();
        let l0 = (0..n)
            .map(|e| {
                let a = gather::<2>(&le, e, x);
                ((a[1][0] - a[0][0]).powi(2)
                    + (a[1][1] - a[0][1]).powi(2)
                    + (a[1][2] - a[0][2]).powi(2))
                .sqrt()
            })
            .collect();
        let state = (0..n)
            .map(|e| spring::spring_init(&gather::<2>(&le, e, x)))
            .collect();
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
            props: sp,
            fcts,
            prop_of,
            l0,
            state,
            alive: vec![true; n],
            steps: vec![ElemStep::default(); n],
            masses,
        })
    }
}

impl Block for SpringBlock {
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
        _vr: &[[f64; 3]],
        dt: f64,
        contrib: &mut [[f64; SLOT]],
    ) {
        let (le, props, fcts, prop_of, l0, masses) = (
            &self.le,
            &self.props,
            &self.fcts,
            &self.prop_of,
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
                let p = prop_of[e] as usize;
                let o = spring::spring_step(
                    &props[p],
                    fcts[p].as_ref(),
                    &gather::<2>(le, e, x),
                    &gather::<2>(le, e, v),
                    l0[e],
                    dt,
                    st,
                );
                for k in 0..2 {
                    c[k] = [o.f[k][0], o.f[k][1], o.f[k][2], 0.0, 0.0, 0.0];
                }
                // Two masses on a spring: ω² = k(1/m1 + 1/m2), Δt = (2/ω)(√(1+ξ²) − ξ).
                let [m1, m2] = masses[e];
                let dt_e = if o.k_eff > 0.0 && m1 > 0.0 && m2 > 0.0 {
                    let mu = m1 * m2 / (m1 + m2);
                    let w = (o.k_eff / mu).sqrt();
                    let xi = o.c_eff / (2.0 * (o.k_eff * mu).sqrt());
                    (2.0 / w) * ((1.0 + xi * xi).sqrt() - xi)
                } else {
                    f64::INFINITY
                };
                *out = ElemStep {
                    dt: dt_e,
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
                (
                    self.le.global[e],
                    [
                        self.state[e].force,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        self.state[e].eint,
                        if self.alive[e] { 0.0 } else { 1.0 },
                    ],
                )
            })
            .collect()
    }
    fn outputs(&self) -> Vec<ElemOut> {
        self.state
            .iter()
            .zip(&self.alive)
            .map(|(s, &alive)| ElemOut {
                von_mises: s.force.abs(),
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

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(SpringBlock::new(
        input.le,
        input.x,
        input.mass,
        input.parts,
        input.props,
        input.functions,
    )?))
}
