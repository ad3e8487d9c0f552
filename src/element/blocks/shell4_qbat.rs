//! QBAT 4-node shells (Radioss Ishell = 12; kernel in
//! `crate::element::shell4_qbat`).

use super::common::{decode_state, gather, settle_common};
use super::sections::{part_material, per_part, shell_property, SHELL_WITHOUT_MATERIAL};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::shell4_qbat::{membrane_von_mises, qbat_step, QbatSection, QbatState};
use crate::element::SLOT;
use crate::material::Material;
use crate::model::{ElementKind, MaterialSpec, Part, Property};
use rayon::prelude::*;

pub struct QbatBlock {
    le: LocalElements,
    sections: Vec<QbatSection>,
    section: Vec<u16>,
    state: Vec<QbatState>,
    alive: Vec<bool>,
    steps: Vec<ElemStep>,
}

impl QbatBlock {
    pub fn new(
        le: LocalElements,
        parts: &[Part],
        props: &[Property],
        mats: &[MaterialSpec],
    ) -> Result<Self, String> {
        let (sections, section) = per_part(&le, |p| {
            let part = &parts[p as usize];
            let r = shell_property(part, props)?;
            let card = part_material(part, mats, SHELL_WITHOUT_MATERIAL)?;
            if !card.failures.is_empty() {
                return Err(format!(
                    "{}: a failure model on a QBAT shell (Ishell = 12) is not computed yet",
                    card.loc
                ));
            }
            // Idrill 2 (and 0 resolved) is "no drilling dof".
            if r.ithick == 1 || r.idrill == 1 {
                return Err(format!(
                    "Ishell = 12 (QBAT) with Ithick = {} and Idrill = {}: the thickness change and the drilling stiffness are not computed on QBAT yet",
                    r.ithick, r.idrill
                ));
            }
            let dn = if r.dn > 0.0 { r.dn } else { 1e-3 };
            QbatSection::new(r.thick, r.ashear, dn, &Material::from_card(card))
        })?;
        let n = le.global.len();
        Ok(QbatBlock {
            le,
            sections,
            section,
            state: vec![QbatState::default(); n],
            alive: vec![true; n],
            steps: vec![ElemStep::default(); n],
        })
    }
}

impl Block for QbatBlock {
    fn kind(&self) -> ElementKind {
        ElementKind::Shell4
    }
    fn local(&self) -> &LocalElements {
        &self.le
    }
    fn corners(&self) -> usize {
        4
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
        contrib
            .par_chunks_mut(4)
            .zip(self.state.par_iter_mut())
            .zip(self.steps.par_iter_mut())
            .enumerate()
            .for_each(|(e, ((c, st), out))| {
                let w = if vr.is_empty() {
                    [[0.0; 3]; 4]
                } else {
                    gather::<4>(le, e, vr)
                };
                let o = qbat_step(
                    &sections[section[e] as usize],
                    &gather::<4>(le, e, x),
                    &gather::<4>(le, e, v),
                    &w,
                    dt,
                    st,
                );
                c.copy_from_slice(&o.f);
                *out = ElemStep {
                    dt: o.dt,
                    failed: false,
                    bad: !(o.dt > 0.0),
                };
            });
    }
    fn steps(&self) -> &[ElemStep] {
        &self.steps
    }
    fn nodal_step_factor(&self, e: usize) -> f64 {
        let sec = &self.sections[self.section[e] as usize];
        crate::element::step_stiffness::quad_physical_factor(sec.material.poisson())
    }
    fn settle(&mut self) -> Option<(u32, &'static str)> {
        settle_common(
            &mut self.alive,
            &self.steps,
            &self.le,
            "is degenerate (zero area or a zero diagonal)",
        )
    }
    fn alive(&self, e: usize) -> bool {
        self.alive[e]
    }
    fn rows(&self) -> Vec<ElemRow> {
        (0..self.le.global.len())
            .map(|e| {
                let (s, t) = (
                    &self.state[e],
                    self.sections[self.section[e] as usize].thick,
                );
                let n = |k: usize| s.res.iter().map(|r| r[k]).sum::<f64>() / (4.0 * t);
                (
                    self.le.global[e],
                    [n(0), n(1), s.n12 / t, 0.0, t, s.eint, 0.0],
                )
            })
            .collect()
    }
    fn outputs(&self) -> Vec<ElemOut> {
        (0..self.le.global.len())
            .map(|e| {
                let (s, t) = (
                    &self.state[e],
                    self.sections[self.section[e] as usize].thick,
                );
                ElemOut {
                    von_mises: membrane_von_mises(s, t),
                    eps_p: 0.0,
                    thick: t,
                    eint: s.eint,
                    ehg: 0.0,
                    eplas: 0.0,
                    deleted: !self.alive[e],
                }
            })
            .collect()
    }
    fn export_state(&self, e: usize) -> Vec<u8> {
        bincode::serialize(&(&self.state[e], self.alive[e])).expect("element state serializes")
    }
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
        let (st, alive): (QbatState, bool) = decode_state(bytes, "QBAT shell")?;
        self.state[e] = st;
        self.alive[e] = alive;
        Ok(())
    }
}

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(QbatBlock::new(
        input.le,
        input.parts,
        input.props,
        input.mats,
    )?))
}
