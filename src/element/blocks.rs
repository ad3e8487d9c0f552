//! One rank's elements, a block per kind. A block runs its kernel over its
//! elements (rayon, one element per task, each writing only its own corner
//! slots), reports its smallest time step and its energy, and lists its
//! final state. The solver sees every kind through the `Block` trait.

use super::SLOT;
use crate::domain::LocalElements;
use crate::element::hex8::{self, Hex8State, SolidSection};
use crate::element::shell3::{self, Shell3State};
use crate::element::shell4::{self, Shell4State, ShellSection};
use crate::element::spring::{self, SpringState};
use crate::element::tet4::{self, Tet4State};
use crate::material::Material;
use crate::model::{ElementKind, Function, PropertyKind, SpringProperty};
use crate::model::{Part, Property};
use rayon::prelude::*;
use std::collections::HashMap;

/// Per-element result the solver needs after a step.
#[derive(Clone, Copy, Debug, Default)]
pub struct ElemStep {
    pub dt: f64,
    pub failed: bool,
    pub bad: bool,
}

/// Final per-element values for --final-elements: sxx, syy, sxy, eps_p, thick, eint, deleted.
pub type ElemRow = (u32, [f64; 7]);

/// Per-element values written to the HDF5 states and time histories
/// (`crate::output`), one per local element in the block's (global) order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ElemOut {
    /// Von Mises stress: shells the largest over the through-thickness
    /// points (plane stress with the transverse shears), solids from the
    /// full tensor, springs |force|.
    pub von_mises: f64,
    /// Effective plastic strain (shells: largest over the points).
    pub eps_p: f64,
    /// Current thickness (shells; 0 for the others).
    pub thick: f64,
    /// Internal energy with hourglass.
    pub eint: f64,
    /// Hourglass energy (part of `eint`; Radioss reports it apart from the
    /// listing's and the time histories' internal energy).
    pub ehg: f64,
    pub deleted: bool,
}

/// Von Mises stress of a shell point [σxx σyy σxy σyz σzx] (σzz = 0).
fn von_mises_shell(s: &[f64; 5]) -> f64 {
    (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * (s[2] * s[2] + s[3] * s[3] + s[4] * s[4]))
        .max(0.0)
        .sqrt()
}

/// Von Mises stress of a 3-D tensor [σxx σyy σzz σxy σyz σzx].
fn von_mises_3d(s: &[f64; 6]) -> f64 {
    let d = (s[0] - s[1]).powi(2) + (s[1] - s[2]).powi(2) + (s[2] - s[0]).powi(2);
    (0.5 * d + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]))
        .max(0.0)
        .sqrt()
}

/// Decodes one element's restart record, naming what did not fit.
fn decode_state<T: serde::de::DeserializeOwned>(bytes: &[u8], what: &str) -> Result<T, String> {
    bincode::deserialize(bytes).map_err(|e| format!("{what} element state does not decode: {e}"))
}

pub trait Block: Send + Sync {
    fn kind(&self) -> ElementKind;
    fn local(&self) -> &LocalElements;
    /// Corner slots per element (force + moment each).
    fn corners(&self) -> usize;
    /// Runs every live element; writes `corners()` slots per element into `contrib`.
    fn compute(
        &mut self,
        x: &[[f64; 3]],
        v: &[[f64; 3]],
        vr: &[[f64; 3]],
        dt: f64,
        contrib: &mut [[f64; SLOT]],
    );
    /// Per-element step results of the last `compute`.
    fn steps(&self) -> &[ElemStep];
    /// Marks failed elements deleted; returns the first element with a bad
    /// geometry (global index within the kind, what is wrong).
    fn settle(&mut self) -> Option<(u32, &'static str)>;
    fn alive(&self, e: usize) -> bool;
    /// Internal energy (with hourglass) of the block's elements.
    fn energy(&self) -> f64;
    /// Hourglass energy and plastic work (parts of `energy`).
    fn energy_parts(&self) -> (f64, f64) {
        (0.0, 0.0)
    }
    fn rows(&self) -> Vec<ElemRow>;
    /// Values for the HDF5 states, one per local element (see `ElemOut`).
    fn outputs(&self) -> Vec<ElemOut>;
    /// Everything the element needs to continue after a restart (its state,
    /// integration-point stresses and strains, deleted flag), as bytes; the
    /// restart file keys it by the element's global index (`local().global[e]`).
    fn export_state(&self, e: usize) -> Vec<u8>;
    /// Puts back what `export_state` saved (possibly on another rank count).
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String>;
}

fn gather<const N: usize>(le: &LocalElements, e: usize, a: &[[f64; 3]]) -> [[f64; 3]; N] {
    std::array::from_fn(|k| a[le.nodes[N * e + k] as usize])
}

fn settle_common(
    alive: &mut [bool],
    steps: &[ElemStep],
    le: &LocalElements,
    what: &'static str,
) -> Option<(u32, &'static str)> {
    let mut problem = None;
    for e in 0..alive.len() {
        if !alive[e] {
            continue;
        }
        if steps[e].bad && problem.is_none() {
            problem = Some((le.global[e], what));
        }
        if steps[e].failed {
            alive[e] = false;
        }
    }
    problem
}

// ---- shells (4- and 3-node) -------------------------------------------------

/// Shell sections per part (built once per part used).
fn shell_sections(
    le: &LocalElements,
    parts: &[Part],
    props: &[Property],
    mats: &[crate::model::MaterialSpec],
    tri: bool,
) -> Result<(Vec<ShellSection>, Vec<u16>), String> {
    let mut sections = Vec::new();
    let mut of_part: HashMap<u32, u16> = HashMap::new();
    let mut section = Vec::with_capacity(le.part.len());
    for &p in &le.part {
        let s = match of_part.get(&p) {
            Some(&s) => s,
            None => {
                let part = &parts[p as usize];
                let prop = props[part.prop.ok_or("shell part without property")? as usize]
                    .shell
                    .as_ref()
                    .ok_or("shell part without a shell property")?;
                let mat = Material::from_card(
                    &mats[part.mat.ok_or("shell part without material")? as usize],
                );
                sections.push(if tri {
                    shell3::shell3_section(prop, &mat)?
                } else {
                    ShellSection::new(prop, &mat)?
                });
                of_part.insert(p, (sections.len() - 1) as u16);
                (sections.len() - 1) as u16
            }
        };
        section.push(s);
    }
    Ok((sections, section))
}

/// 4-node and 3-node shells share this shape: a section per part, `nip`
/// integration points per element (stress and plastic strain), rotations.
macro_rules! shell_block {
    ($name:ident, $kind:expr, $nn:literal, $state:ty, $init:path, $step:path, $tri:expr) => {
        pub struct $name {
            le: LocalElements,
            sections: Vec<ShellSection>,
            section: Vec<u16>,
            state: Vec<$state>,
            sig: Vec<[f64; 5]>,
            eps_p: Vec<f64>,
            nip: usize,
            alive: Vec<bool>,
            steps: Vec<ElemStep>,
        }

        impl $name {
            pub fn new(
                le: LocalElements,
                x: &[[f64; 3]],
                parts: &[Part],
                props: &[Property],
                mats: &[crate::model::MaterialSpec],
            ) -> Result<Self, String> {
                let (sections, section) = shell_sections(&le, parts, props, mats, $tri)?;
                let n = le.global.len();
                let nip = sections.iter().map(|s| s.n_ip).max().unwrap_or(1).max(1);
                let state = (0..n)
                    .map(|e| {
                        $init(
                            &sections[section[e] as usize],
                            &gather::<$nn>(&le, e, x),
                            le.thick[e],
                        )
                    })
                    .collect();
                Ok($name {
                    le,
                    sections,
                    section,
                    state,
                    sig: vec![[0.0; 5]; n * nip],
                    eps_p: vec![0.0; n * nip],
                    nip,
                    alive: vec![true; n],
                    steps: vec![ElemStep::default(); n],
                })
            }
        }

        impl Block for $name {
            fn kind(&self) -> ElementKind {
                $kind
            }
            fn local(&self) -> &LocalElements {
                &self.le
            }
            fn corners(&self) -> usize {
                $nn
            }
            fn compute(
                &mut self,
                x: &[[f64; 3]],
                v: &[[f64; 3]],
                vr: &[[f64; 3]],
                dt: f64,
                contrib: &mut [[f64; SLOT]],
            ) {
                let (le, sections, section, nip) =
                    (&self.le, &self.sections, &self.section, self.nip);
                contrib
                    .par_chunks_mut($nn)
                    .zip(self.state.par_iter_mut())
                    .zip(self.sig.par_chunks_mut(nip))
                    .zip(self.eps_p.par_chunks_mut(nip))
                    .zip(self.steps.par_iter_mut())
                    .zip(self.alive.par_iter())
                    .enumerate()
                    .for_each(|(e, (((((c, st), sig), eps), out), alive))| {
                        if !*alive {
                            c.iter_mut().for_each(|s| *s = [0.0; SLOT]);
                            *out = ElemStep {
                                dt: f64::INFINITY,
                                ..Default::default()
                            };
                            return;
                        }
                        let sec = &sections[section[e] as usize];
                        let n = sec.n_ip.max(1);
                        let o = $step(
                            sec,
                            &gather::<$nn>(le, e, x),
                            &gather::<$nn>(le, e, v),
                            &gather::<$nn>(le, e, vr),
                            dt,
                            st,
                            &mut sig[..n],
                            &mut eps[..n],
                        );
                        for k in 0..$nn {
                            c[k] = [
                                o.f[k][0], o.f[k][1], o.f[k][2], o.m[k][0], o.m[k][1], o.m[k][2],
                            ];
                        }
                        *out = ElemStep {
                            dt: o.dt,
                            failed: o.failed,
                            bad: o.bad_area,
                        };
                    });
            }
            fn steps(&self) -> &[ElemStep] {
                &self.steps
            }
            fn settle(&mut self) -> Option<(u32, &'static str)> {
                settle_common(
                    &mut self.alive,
                    &self.steps,
                    &self.le,
                    "has a zero or negative area (inverted element)",
                )
            }
            fn alive(&self, e: usize) -> bool {
                self.alive[e]
            }
            fn energy(&self) -> f64 {
                self.state.iter().map(|s| s.eint + hourglass_of(s)).sum()
            }
            fn energy_parts(&self) -> (f64, f64) {
                (
                    self.state.iter().map(hourglass_of).sum(),
                    self.state.iter().map(|s| s.eplas).sum(),
                )
            }
            fn rows(&self) -> Vec<ElemRow> {
                (0..self.le.global.len())
                    .map(|e| {
                        let n = self.sections[self.section[e] as usize].n_ip.max(1);
                        let sig = &self.sig[e * self.nip..e * self.nip + n];
                        let mean = |k: usize| sig.iter().map(|s| s[k]).sum::<f64>() / n as f64;
                        let epsp = self.eps_p[e * self.nip..e * self.nip + n]
                            .iter()
                            .fold(0.0f64, |a, &b| a.max(b));
                        let st = &self.state[e];
                        (
                            self.le.global[e],
                            [
                                mean(0),
                                mean(1),
                                mean(2),
                                epsp,
                                st.thick,
                                st.eint + hourglass_of(st),
                                if self.alive[e] { 0.0 } else { 1.0 },
                            ],
                        )
                    })
                    .collect()
            }
            fn outputs(&self) -> Vec<ElemOut> {
                (0..self.le.global.len())
                    .map(|e| {
                        let n = self.sections[self.section[e] as usize].n_ip.max(1);
                        let pts = e * self.nip..e * self.nip + n;
                        let st = &self.state[e];
                        ElemOut {
                            von_mises: self.sig[pts.clone()]
                                .iter()
                                .map(von_mises_shell)
                                .fold(0.0, f64::max),
                            eps_p: self.eps_p[pts].iter().fold(0.0f64, |a, &b| a.max(b)),
                            thick: st.thick,
                            eint: st.eint + hourglass_of(st),
                            ehg: hourglass_of(st),
                            deleted: !self.alive[e],
                        }
                    })
                    .collect()
            }
            fn export_state(&self, e: usize) -> Vec<u8> {
                let n = self.sections[self.section[e] as usize].n_ip.max(1);
                let pts = e * self.nip..e * self.nip + n;
                bincode::serialize(&(
                    &self.state[e],
                    &self.sig[pts.clone()],
                    &self.eps_p[pts],
                    self.alive[e],
                ))
                .expect("element state serializes")
            }
            fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
                let (st, sig, eps, alive): ($state, Vec<[f64; 5]>, Vec<f64>, bool) =
                    decode_state(bytes, "shell")?;
                let n = self.sections[self.section[e] as usize].n_ip.max(1);
                if sig.len() != n || eps.len() != n {
                    return Err(format!(
                        "shell element state has {} integration points, the section has {n}",
                        sig.len()
                    ));
                }
                self.state[e] = st;
                self.sig[e * self.nip..e * self.nip + n].copy_from_slice(&sig);
                self.eps_p[e * self.nip..e * self.nip + n].copy_from_slice(&eps);
                self.alive[e] = alive;
                Ok(())
            }
        }
    };
}

shell_block!(
    Shell4Block,
    ElementKind::Shell4,
    4,
    Shell4State,
    shell4::shell4_init,
    shell4::shell4_step,
    false
);
shell_block!(
    Shell3Block,
    ElementKind::Shell3,
    3,
    Shell3State,
    shell3::shell3_init,
    shell3::shell3_step,
    true
);

// ---- solids ------------------------------------------------------------------

fn solid_sections(
    le: &LocalElements,
    parts: &[Part],
    props: &[Property],
    mats: &[crate::model::MaterialSpec],
    tetra: bool,
) -> Result<(Vec<SolidSection>, Vec<u16>), String> {
    let mut sections = Vec::new();
    let mut of_part: HashMap<u32, u16> = HashMap::new();
    let mut section = Vec::with_capacity(le.part.len());
    for &p in &le.part {
        let s = match of_part.get(&p) {
            Some(&s) => s,
            None => {
                let part = &parts[p as usize];
                let prop = props[part.prop.ok_or("solid part without property")? as usize]
                    .solid
                    .as_ref()
                    .ok_or("solid part without a solid property")?;
                let mat = Material::from_card(
                    &mats[part.mat.ok_or("solid part without material")? as usize],
                );
                sections.push(if tetra {
                    SolidSection::for_tetra(prop, &mat)?
                } else {
                    SolidSection::new(prop, &mat)?
                });
                of_part.insert(p, (sections.len() - 1) as u16);
                (sections.len() - 1) as u16
            }
        };
        section.push(s);
    }
    Ok((sections, section))
}

/// 8-node bricks and 4-node tetrahedra share this shape: one state per element, no rotations.
macro_rules! solid_block {
    ($name:ident, $kind:expr, $nn:literal, $state:ty, $init:path, $step:path, $tetra:expr) => {
        pub struct $name {
            le: LocalElements,
            sections: Vec<SolidSection>,
            section: Vec<u16>,
            state: Vec<$state>,
            alive: Vec<bool>,
            steps: Vec<ElemStep>,
        }

        impl $name {
            pub fn new(
                le: LocalElements,
                x: &[[f64; 3]],
                parts: &[Part],
                props: &[Property],
                mats: &[crate::model::MaterialSpec],
            ) -> Result<Self, String> {
                let (sections, section) = solid_sections(&le, parts, props, mats, $tetra)?;
                let n = le.global.len();
                let state = (0..n)
                    .map(|e| $init(&sections[section[e] as usize], &gather::<$nn>(&le, e, x)))
                    .collect();
                Ok($name {
                    le,
                    sections,
                    section,
                    state,
                    alive: vec![true; n],
                    steps: vec![ElemStep::default(); n],
                })
            }
        }

        impl Block for $name {
            fn kind(&self) -> ElementKind {
                $kind
            }
            fn local(&self) -> &LocalElements {
                &self.le
            }
            fn corners(&self) -> usize {
                $nn
            }
            fn compute(
                &mut self,
                x: &[[f64; 3]],
                v: &[[f64; 3]],
                _vr: &[[f64; 3]],
                dt: f64,
                contrib: &mut [[f64; SLOT]],
            ) {
                let (le, sections, section) = (&self.le, &self.sections, &self.section);
                contrib
                    .par_chunks_mut($nn)
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
                        let o = $step(
                            &sections[section[e] as usize],
                            &gather::<$nn>(le, e, x),
                            &gather::<$nn>(le, e, v),
                            dt,
                            st,
                        );
                        for k in 0..$nn {
                            c[k] = [o.f[k][0], o.f[k][1], o.f[k][2], 0.0, 0.0, 0.0];
                        }
                        *out = ElemStep {
                            dt: o.dt,
                            failed: o.failed,
                            bad: o.bad_volume,
                        };
                    });
            }
            fn steps(&self) -> &[ElemStep] {
                &self.steps
            }
            fn settle(&mut self) -> Option<(u32, &'static str)> {
                settle_common(
                    &mut self.alive,
                    &self.steps,
                    &self.le,
                    "has a zero or negative volume (inverted element)",
                )
            }
            fn alive(&self, e: usize) -> bool {
                self.alive[e]
            }
            fn energy(&self) -> f64 {
                self.state.iter().map(|s| s.eint + hourglass_of(s)).sum()
            }
            fn rows(&self) -> Vec<ElemRow> {
                (0..self.le.global.len())
                    .map(|e| {
                        let s = &self.state[e];
                        (
                            self.le.global[e],
                            [
                                s.sig[0],
                                s.sig[1],
                                s.sig[3],
                                s.eps_p,
                                0.0,
                                s.eint + hourglass_of(s),
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
                        von_mises: von_mises_3d(&s.sig),
                        eps_p: s.eps_p,
                        thick: 0.0,
                        eint: s.eint + hourglass_of(s),
                        ehg: hourglass_of(s),
                        deleted: !alive,
                    })
                    .collect()
            }
            fn export_state(&self, e: usize) -> Vec<u8> {
                bincode::serialize(&(&self.state[e], self.alive[e]))
                    .expect("element state serializes")
            }
            fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
                let (st, alive): ($state, bool) = decode_state(bytes, "solid")?;
                self.state[e] = st;
                self.alive[e] = alive;
                Ok(())
            }
        }
    };
}

/// Hourglass energy kept by an element state (0 for elements without hourglass modes).
trait HourglassEnergy {
    fn hourglass_energy(&self) -> f64;
}
impl HourglassEnergy for Shell4State {
    fn hourglass_energy(&self) -> f64 {
        self.ehg
    }
}
impl HourglassEnergy for Shell3State {
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
}
impl HourglassEnergy for Hex8State {
    fn hourglass_energy(&self) -> f64 {
        self.ehg
    }
}
impl HourglassEnergy for Tet4State {
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
}
fn hourglass_of<S: HourglassEnergy>(s: &S) -> f64 {
    s.hourglass_energy()
}

solid_block!(
    Hex8Block,
    ElementKind::Brick8,
    8,
    Hex8State,
    hex8::hex8_init,
    hex8::hex8_step,
    false
);
solid_block!(
    Tet4Block,
    ElementKind::Tetra4,
    4,
    Tet4State,
    tet4::tet4_init,
    tet4::tet4_step,
    true
);

// ---- springs -----------------------------------------------------------------

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
    fn energy(&self) -> f64 {
        self.state.iter().map(|s| s.eint).sum()
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

/// The block for one kind of local elements (empty kinds get none).
pub fn make_block(
    le: &LocalElements,
    x: &[[f64; 3]],
    mass: &[f64],
    parts: &[Part],
    props: &[Property],
    mats: &[crate::model::MaterialSpec],
    functions: &[Function],
) -> Result<Option<Box<dyn Block>>, String> {
    if le.global.is_empty() {
        return Ok(None);
    }
    let le = le.clone();
    Ok(Some(match le.kind {
        ElementKind::Shell4 => Box::new(Shell4Block::new(le, x, parts, props, mats)?),
        ElementKind::Shell3 => Box::new(Shell3Block::new(le, x, parts, props, mats)?),
        ElementKind::Brick8 => Box::new(Hex8Block::new(le, x, parts, props, mats)?),
        ElementKind::Tetra4 => Box::new(Tet4Block::new(le, x, parts, props, mats)?),
        ElementKind::Spring => Box::new(SpringBlock::new(le, x, mass, parts, props, functions)?),
        ElementKind::Truss | ElementKind::Beam => {
            return Err(format!(
                "{} elements are not computed by the engine yet",
                le.kind.keyword()
            ))
        }
    }))
}
