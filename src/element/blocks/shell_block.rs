//! The shape 4-node and 3-node shell blocks share (`shell_block!`).

/// 4-node and 3-node shells share this shape: a section per part, `nip`
/// integration points per element (stress and plastic strain), rotations.
macro_rules! shell_block {
    ($name:ident, $kind:expr, $nn:literal, $state:ty, $init:path, $step:path, $section:path, $stiff:expr, $batch:expr) => {
        pub struct $name {
            le: LocalElements,
            sections: Vec<ShellSection>,
            section: Vec<u16>,
            state: Vec<$state>,
            sig: Vec<[f64; 5]>,
            eps_p: Vec<f64>,
            /// Per point history beyond ε_p (`shell4::PointHistory`).
            dmg: Vec<PointHistory>,
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
                let (sections, section) = shell_sections(&le, parts, props, mats, $section)?;
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
                    dmg: vec![[0.0; 3]; n * nip],
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
                let batch: Option<BatchFn<$nn, $state>> = $batch;
                // Four elements at a time: one batch where the formulation
                // has one and they share a section, else one by one (the
                // same answer either way, see `element::lanes`).
                contrib
                    .par_chunks_mut(4 * $nn)
                    .zip(self.state.par_chunks_mut(4))
                    .zip(self.sig.par_chunks_mut(4 * nip))
                    .zip(self.eps_p.par_chunks_mut(4 * nip))
                    .zip(self.dmg.par_chunks_mut(4 * nip))
                    .zip(self.steps.par_chunks_mut(4))
                    .zip(self.alive.par_chunks(4))
                    .enumerate()
                    .for_each(|(b, ((((((c, st), sig), eps), dmg), out), alive))| {
                        let e0 = 4 * b;
                        let sec = &sections[section[e0] as usize];
                        if let Some(step4) = batch {
                            if st.len() == 4
                                && alive.iter().all(|&a| a)
                                && section[e0..e0 + 4].iter().all(|&s| s == section[e0])
                            {
                                let g = |a: &[[f64; 3]]| {
                                    let n = |i| gather::<$nn>(le, e0 + i, a);
                                    [n(0), n(1), n(2), n(3)]
                                };
                                let o =
                                    step4(sec, &g(x), &g(v), &g(vr), dt, st, sig, eps, dmg, nip);
                                if let Some(o) = o {
                                    for (i, o) in o.iter().enumerate() {
                                        corner_slots(&mut c[$nn * i..$nn * (i + 1)], &o.f, &o.m);
                                        out[i] = ElemStep {
                                            dt: o.dt,
                                            failed: o.failed,
                                            bad: o.bad_area,
                                        };
                                    }
                                    return;
                                }
                            }
                        }
                        for i in 0..st.len() {
                            let e = e0 + i;
                            let c = &mut c[$nn * i..$nn * (i + 1)];
                            if !alive[i] {
                                c.iter_mut().for_each(|s| *s = [0.0; SLOT]);
                                out[i] = ElemStep {
                                    dt: f64::INFINITY,
                                    ..Default::default()
                                };
                                continue;
                            }
                            let sec = &sections[section[e] as usize];
                            let n = sec.n_ip.max(1);
                            let pts = i * nip..i * nip + n;
                            let o = $step(
                                sec,
                                &gather::<$nn>(le, e, x),
                                &gather::<$nn>(le, e, v),
                                &gather::<$nn>(le, e, vr),
                                dt,
                                &mut st[i],
                                &mut sig[pts.clone()],
                                &mut eps[pts.clone()],
                                &mut dmg[pts],
                            );
                            corner_slots(c, &o.f, &o.m);
                            out[i] = ElemStep {
                                dt: o.dt,
                                failed: o.failed,
                                bad: o.bad_area,
                            };
                        }
                    });
            }
            fn steps(&self) -> &[ElemStep] {
                &self.steps
            }
            fn nodal_step_factor(&self, e: usize) -> f64 {
                crate::element::step_stiffness::shell_factor(
                    $kind,
                    &self.sections[self.section[e] as usize],
                )
            }
            fn nodal_stiffness(&self, x: &[[f64; 3]], contrib: &mut [[f64; SLOT]]) -> bool {
                let stiff: Option<NodalStiffnessFn<$nn>> = $stiff;
                let Some(f) = stiff else {
                    return false;
                };
                let (le, sections, section) = (&self.le, &self.sections, &self.section);
                contrib
                    .par_chunks_mut($nn)
                    .zip(self.state.par_iter())
                    .zip(self.alive.par_iter())
                    .enumerate()
                    .for_each(|(e, ((c, st), alive))| {
                        let (k, kr) = if *alive {
                            f(
                                &sections[section[e] as usize],
                                &gather::<$nn>(le, e, x),
                                st.thick,
                            )
                        } else {
                            (0.0, 0.0)
                        };
                        c.iter_mut().for_each(|s| *s = [k, 0.0, 0.0, kr, 0.0, 0.0]);
                    });
                true
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
                            eplas: st.plastic_work(),
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
                    &self.eps_p[pts.clone()],
                    &self.dmg[pts],
                    self.alive[e],
                ))
                .expect("element state serializes")
            }
            fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
                let (st, sig, eps, dmg, alive): (
                    $state,
                    Vec<[f64; 5]>,
                    Vec<f64>,
                    Vec<PointHistory>,
                    bool,
                ) = decode_state(bytes, "shell")?;
                let n = self.sections[self.section[e] as usize].n_ip.max(1);
                if sig.len() != n || eps.len() != n || dmg.len() != n {
                    return Err(format!(
                        "shell element state has {} integration points, the section has {n}",
                        sig.len()
                    ));
                }
                self.state[e] = st;
                self.sig[e * self.nip..e * self.nip + n].copy_from_slice(&sig);
                self.eps_p[e * self.nip..e * self.nip + n].copy_from_slice(&eps);
                self.dmg[e * self.nip..e * self.nip + n].copy_from_slice(&dmg);
                self.alive[e] = alive;
                Ok(())
            }
        }
    };
}

pub(super) use shell_block;

/// A shell formulation's nodal stiffness (K, K_rot) of one element for the
/// nodal time step: its section, corners and thickness.
pub(super) type NodalStiffnessFn<const N: usize> =
    fn(&crate::element::shell4::ShellSection, &[[f64; 3]; N], f64) -> (f64, f64);

/// An element's corner forces and moments into its contribution slots.
pub(super) fn corner_slots<const N: usize>(
    c: &mut [[f64; crate::element::SLOT]],
    f: &[[f64; 3]; N],
    m: &[[f64; 3]; N],
) {
    for k in 0..N {
        c[k] = [f[k][0], f[k][1], f[k][2], m[k][0], m[k][1], m[k][2]];
    }
}

/// A formulation's step of four elements of one section (corners, velocities,
/// rotational velocities, Δt, their states and `nip`-strided points), or
/// `None` with nothing changed where they must go one by one.
pub(super) type BatchFn<const N: usize, S> = fn(
    &crate::element::shell4::ShellSection,
    &[[[f64; 3]; N]; 4],
    &[[[f64; 3]; N]; 4],
    &[[[f64; 3]; N]; 4],
    f64,
    &mut [S],
    &mut [[f64; 5]],
    &mut [f64],
    &mut [crate::element::shell4::PointHistory],
    usize,
) -> Option<[crate::element::shell4::Shell4Out; 4]>;
