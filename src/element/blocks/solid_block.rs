//! The shape brick and tetrahedron blocks share (`solid_block!`).

/// 8-node bricks and 4-node tetrahedra share this shape: one state per element, no rotations.
macro_rules! solid_block {
    ($name:ident, $kind:expr, $nn:literal, $state:ty, $init:path, $step:path, $section:path) => {
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
                let (sections, section) = solid_sections(&le, parts, props, mats, $section)?;
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
            fn nodal_stiffness(&self, x: &[[f64; 3]], contrib: &mut [[f64; SLOT]]) -> bool {
                use super::common::SolidNodalStiffness;
                let (le, sections, section) = (&self.le, &self.sections, &self.section);
                let ks: Vec<Option<f64>> = self
                    .state
                    .par_iter()
                    .zip(self.alive.par_iter())
                    .enumerate()
                    .map(|(e, (st, alive))| {
                        let k = st.corner_stiffness(
                            &sections[section[e] as usize],
                            &gather::<$nn>(le, e, x),
                        );
                        if *alive {
                            k
                        } else {
                            k.map(|_| 0.0)
                        }
                    })
                    .collect();
                if ks.iter().any(Option::is_none) {
                    return false;
                }
                contrib
                    .par_chunks_mut($nn)
                    .zip(ks.par_iter())
                    .for_each(|(c, k)| {
                        let k = k.unwrap_or(0.0);
                        c.iter_mut().for_each(|s| *s = [k, 0.0, 0.0, 0.0, 0.0, 0.0]);
                    });
                true
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
                        eplas: s.plastic_work(),
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

pub(super) use solid_block;
