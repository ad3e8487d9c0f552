//! Run outputs besides the listing: the parallel HDF5 run file with its
//! XDMF description, time histories, restart files, the progress line, and
//! the `info` and `plot` commands that read the run file back.
//!
//! The solver loop (`solver::run`) calls three hooks and keeps its own
//! variables; the hooks see them through `LoopState`, a struct of
//! references built in place:
//!
//! - `Output::start` before the first cycle: restores a restart file
//!   (`--restart`) into the loop state, creates (or, after a restart,
//!   reopens) `DIR/NAME.h5`, writes `/mesh`, the initial state and sample;
//! - `Output::after_cycle` at the end of every cycle: time-history samples
//!   every /TFILE period, a state every /ANIM/DT, a restart file every
//!   /RFILE cycles, the progress line, and stop requests (SIGTERM/SIGINT,
//!   `--stop-after-cycle`) agreed over ranks: it returns the listing's
//!   message when the run stops there, the restart file written;
//! - `Output::finish` after the loop: the last state, the last rows, the
//!   XDMF file.
//!
//! Files: `runfile` (the HDF5 layout), `h5` (collective row I/O),
//! `history` (time histories), `xdmf`, `restart` (named sections), `stop`
//! (signals), `progress`, `info` and `plot` (the commands).
//!
//! Contact (later) passes its per-node contact forces and per-interface
//! samples through `LoopState::contact_force` and `LoopState::interfaces`,
//! its interface table through `Context::interfaces`, and adds its restart
//! state as new named sections (see `restart`).

pub mod h5;
pub mod history;
pub mod info;
pub mod mesh_view;
pub mod plot;
pub mod progress;
pub mod raster;
pub mod restart;
pub mod runfile;
pub mod stop;
pub mod text;
pub mod xdmf;

pub use history::InterfaceSample;

use crate::domain::Subdomain;
use crate::element::blocks::Block;
use crate::error::RunError;
use crate::global::GlobalData;
use crate::kinematics::rigid_body::RigidBodyState;
use crate::parallel::{ExactSum, World};
use history::{History, ThRow};
use restart::OutputCounters;
use runfile::RunFile;
use std::path::{Path, PathBuf};

/// The `run` options that concern outputs.
#[derive(Clone, Debug, Default)]
pub struct OutputOptions {
    /// Continue from this restart file.
    pub restart: Option<PathBuf>,
    /// No progress line.
    pub quiet: bool,
    /// The progress line even when stderr is not a terminal (under mpirun,
    /// whose ranks write into pipes that it forwards to the terminal).
    pub progress: bool,
    /// Write the restart file after this cycle and stop (tests, hidden flag).
    pub stop_after_cycle: Option<u64>,
    /// No HDF5/XDMF run file (hidden: to measure what output costs).
    pub no_run_file: bool,
}

/// An interface as the tables of the run file list it.
#[derive(Clone, Debug, PartialEq)]
pub struct InterfaceInfo {
    pub id: u64,
    pub type_number: u32,
    pub title: String,
}

/// What the outputs need besides the loop state.
pub struct Context<'a> {
    pub world: &'a World,
    pub g: &'a GlobalData,
    pub sd: &'a Subdomain,
    pub out_dir: &'a Path,
    pub opts: &'a OutputOptions,
    pub interfaces: &'a [InterfaceInfo],
}

/// The velocities at t^n, the time of the positions, forces and internal
/// energy of a cycle's end. The loop carries velocities at t^{n−½}; the
/// kinetic energy Radioss lists is ½m|v^n|² with v^n = v^{n−½} + ½Δt a^n
/// (`decks/free_plate` against OpenRadioss: the same K-ENERGY T to four
/// digits; ½m|v^{n−½}|² is 7–11% high while the plate rings).
#[derive(Clone, Debug)]
pub struct VelocitiesAtN {
    pub v: Vec<[f64; 3]>,
    pub vr: Vec<[f64; 3]>,
    pub bodies: Vec<RigidBodyState>,
    pub wall_v: Vec<[f64; 3]>,
    /// This rank's external and rigid-wall work of the coming velocity
    /// update (n−½ → n+½), and the share `ahead_weight` of it done by t^n
    /// (Δt^{n−½}/(Δt^{n−½} + Δt^{n+½}), the velocities' own weight): the
    /// listing's EXT-WORK at t^n counts that share, as the kinetic energy
    /// at t^n counts that share of the velocity change (the reference
    /// engine splits an imposed motion's reaction work the same way).
    pub ahead: [ExactSum; 2],
    pub ahead_weight: f64,
}

/// Kinetic energies (translational, rotational) the listing's way, from
/// the velocities, rigid bodies and rigid-wall velocities (collective).
pub type KineticFn<'a> =
    dyn Fn(&[[f64; 3]], &[[f64; 3]], &[RigidBodyState], &[[f64; 3]]) -> (f64, f64) + 'a;

/// The explicit loop's state, by reference: what the restart file saves and
/// restores, and what states and histories are made of. Node arrays are
/// local (the subdomain's numbering), `fint`/`fext` force and moment.
pub struct LoopState<'a> {
    pub t: &'a mut f64,
    pub cycle: &'a mut u64,
    pub dt: &'a mut f64,
    pub dt_prev: &'a mut f64,
    /// What set the time step and its id (the listing's ELEMENT column).
    pub step_what: &'a mut &'static str,
    pub step_id: &'a mut u64,
    pub x: &'a mut [[f64; 3]],
    pub v: &'a mut [[f64; 3]],
    pub vr: &'a mut [[f64; 3]],
    pub fint: &'a mut [[f64; 6]],
    pub fext: &'a mut [[f64; 6]],
    pub blocks: &'a mut [Box<dyn Block>],
    pub bodies: &'a mut [RigidBodyState],
    pub wall_p: &'a mut [[f64; 3]],
    pub wall_v: &'a mut [[f64; 3]],
    /// Per wall, per secondary node held here (the wall's list order).
    pub tied: &'a mut [Vec<bool>],
    /// This rank's partial sums of the external and rigid-wall work.
    pub w_ext: &'a mut ExactSum,
    pub wall_work: &'a mut ExactSum,
    /// The `--history` CSV schedule and samples.
    pub next_th: &'a mut f64,
    pub history: &'a mut Vec<(f64, Vec<[f64; 3]>)>,
    /// Contact and tied interfaces (their state is saved when the deck has
    /// some: `restart`), the contact forces of the last cycle per local
    /// node (they enter the next cycle's velocities), this rank's partial
    /// contact energy, and the fixed degrees of freedom (an impact releases
    /// some: IBC).
    pub contact: &'a mut crate::contact::ContactSystem,
    pub ties: &'a mut crate::contact::tied::TiedSystem,
    pub fcont: &'a mut [[f64; 3]],
    pub e_contact: &'a mut ExactSum,
    pub fixed: &'a mut [[bool; 6]],
    /// Inputs (not saved): the kinetic energy at
    /// t = 0 (energy error), this rank's partial wall forces of the last
    /// cycle, contact forces per local node and this rank's interface
    /// samples (zeros / empty until contact lands).
    pub e0: f64,
    pub wall_force: &'a [[ExactSum; 3]],
    pub contact_force: &'a [[f64; 3]],
    pub interfaces: &'a [InterfaceSample],
    pub kinetic: &'a KineticFn<'a>,
    /// The velocities at t^n when the loop has them (every cycle the
    /// histories sample, and the last); else the kinetic energies and
    /// velocities are those of `v`, `vr` (t = 0 and restarts: the same).
    pub at_n: Option<&'a VelocitiesAtN>,
}

/// The outputs of one run, on every rank.
pub struct Output {
    rank: u32,
    file: Option<RunFile>,
    h5_path: PathBuf,
    /// The XDMF description (written by rank 0).
    xdmf_file: xdmf::XdmfFile,
    rst_path: PathBuf,
    history: History,
    pending: Vec<ThRow>,
    last_th_cycle: Option<u64>,
    states: Vec<(f64, u64)>,
    next_anim: f64,
    anim_period: Option<f64>,
    rfile_cycles: Option<u64>,
    stop_after: Option<u64>,
    hooks: stop::TestHooks,
    progress: progress::Progress,
    xdmf: xdmf::XdmfModel,
    /// The ranks' agreement on stop signals (one cycle behind, non-blocking).
    vote: Box<dyn crate::parallel::StopVote>,
    /// Wall time spent in the hooks (set-up, samples, states, restart files).
    spent: std::time::Duration,
    /// CPU time of the calling thread in the hooks (seconds): on a loaded
    /// machine a steadier measure of what output costs than wall time.
    cpu: f64,
    /// In `finish`: the last state is followed by the close.
    finishing: bool,
}

/// CPU time of the calling thread, in seconds.
pub fn thread_cpu_seconds() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid timespec to write into.
    unsafe {
        libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts);
    }
    ts.tv_sec as f64 + 1e-9 * ts.tv_nsec as f64
}

fn input(e: String) -> RunError {
    RunError::Input(e)
}

impl Output {
    /// Before the first cycle (collective); see the module doc.
    pub fn start(ctx: &Context, s: &mut LoopState) -> Result<Output, RunError> {
        let began = std::time::Instant::now();
        let cpu0 = thread_cpu_seconds();
        h5::ready();
        stop::install();
        let g = ctx.g;
        let world = ctx.world;
        let counters = match &ctx.opts.restart {
            Some(p) => Some(restart::restore(ctx, p, s).map_err(input)?),
            None => None,
        };
        let engine = &g.engine;
        let tstop = engine.run.as_ref().map(|r| r.tstop).unwrap_or(0.0);
        let mut history = History::new(ctx, s.blocks, ctx.interfaces.len());
        let h5_path = ctx.out_dir.join(format!("{}.h5", g.name));
        let xdmf_path = ctx.out_dir.join(format!("{}.xdmf", g.name));
        let rst_path = ctx.out_dir.join(format!("{}_rst.h5", g.name));
        let kinds = runfile::kind_rows(ctx, s.blocks)
            .iter()
            .map(|k| (k.kind, k.total))
            .collect();
        let mut out = Output {
            rank: world.rank(),
            file: None,
            h5_path: h5_path.clone(),
            xdmf_file: xdmf::XdmfFile::new(&xdmf_path),
            rst_path,
            history: History::new(ctx, &[], 0),
            pending: Vec::new(),
            last_th_cycle: None,
            states: Vec::new(),
            next_anim: engine.anim_start,
            anim_period: engine.anim_period.filter(|p| *p > 0.0),
            rfile_cycles: engine.rfile_cycles.filter(|&n| n > 0).map(|n| n as u64),
            stop_after: ctx.opts.stop_after_cycle,
            hooks: stop::TestHooks::from_env(),
            progress: progress::Progress::new(
                world.rank(),
                progress::Mode::of(ctx.opts),
                *s.t,
                *s.cycle,
                tstop,
            ),
            xdmf: xdmf::XdmfModel {
                name: g.name.clone(),
                h5_name: format!("{}.h5", g.name),
                n_nodes: g.node_ids.len(),
                kinds,
            },
            vote: world.stop_vote(),
            spent: std::time::Duration::ZERO,
            cpu: 0.0,
            finishing: false,
        };
        if !ctx.opts.no_run_file {
            // Continue the run file of the run being restarted when it is there.
            let here = h5_path.is_file();
            let exists: bool = world
                .broadcast(if world.rank() == 0 { Some(&here) } else { None })
                .map_err(input)?;
            out.file = Some(match &counters {
                Some(c) if exists => {
                    out.states = c.states.clone();
                    out.next_anim = c.next_anim;
                    history.next = c.next_th;
                    RunFile::reopen(
                        ctx,
                        &h5_path,
                        s.blocks,
                        history.layout,
                        c.states.len(),
                        c.th_rows,
                    )
                    .map_err(input)?
                }
                _ => {
                    if let Some(c) = &counters {
                        out.next_anim = c.next_anim;
                        history.next = c.next_th;
                    }
                    let mut f =
                        RunFile::create(ctx, &h5_path, s.blocks, history.layout).map_err(input)?;
                    if counters.is_some() {
                        // No initial state follows to complete the header on disk.
                        f.checkpoint().map_err(input)?;
                    }
                    f
                }
            });
        } else if let Some(c) = &counters {
            out.next_anim = c.next_anim;
            history.next = c.next_th;
        }
        out.history = history;
        if counters.is_none() {
            // The initial state, whether /ANIM/DT asks for it or not.
            out.outputs(ctx, s, true)?;
        }
        out.spent += began.elapsed();
        // (`outputs` counted its part already: the whole set-up replaces it.)
        out.cpu = thread_cpu_seconds() - cpu0;
        Ok(out)
    }

    /// Samples and states that are due (or a state anyway with `force`).
    fn outputs(&mut self, ctx: &Context, s: &LoopState, force: bool) -> Result<(), RunError> {
        if self.file.is_none() {
            return Ok(());
        }
        let t = *s.t;
        // CPU time is taken only around the work (the clock is a system
        // call; most cycles have nothing to do here).
        if self.history.due(t) || (force && self.last_th_cycle != Some(*s.cycle)) {
            let cpu0 = thread_cpu_seconds();
            let row = self.history.sample(ctx, s);
            self.last_th_cycle = Some(row.cycle);
            self.pending.push(row);
            self.cpu += thread_cpu_seconds() - cpu0;
        }
        let anim_due = self.anim_period.is_some() && t >= self.next_anim;
        let written = self.states.last().map(|st| st.1) == Some(*s.cycle);
        if (anim_due || force) && !written {
            let cpu0 = thread_cpu_seconds();
            let r = self.write_state(ctx, s);
            self.cpu += thread_cpu_seconds() - cpu0;
            r?;
        }
        if let Some(p) = self.anim_period {
            while self.next_anim <= t {
                self.next_anim += p;
            }
        }
        Ok(())
    }

    fn write_state(&mut self, ctx: &Context, s: &LoopState) -> Result<(), RunError> {
        let Some(f) = &mut self.file else {
            return Ok(());
        };
        f.append_th(&self.pending).map_err(input)?;
        self.pending.clear();
        f.write_state(ctx, self.states.len(), s, s.contact_force)
            .map_err(input)?;
        // The file is complete on disk after each state; at the end the
        // close that follows does it.
        if !self.finishing {
            f.checkpoint().map_err(input)?;
        }
        self.states.push((*s.t, *s.cycle));
        if self.rank == 0 {
            let list: Vec<(usize, f64)> = self.states.iter().map(|st| st.0).enumerate().collect();
            self.xdmf_file.update(&self.xdmf, &list).map_err(input)?;
        }
        Ok(())
    }

    /// Puts the pending rows in the file and writes the restart file.
    fn save_restart(&mut self, ctx: &Context, s: &LoopState) -> Result<(), RunError> {
        let cpu0 = thread_cpu_seconds();
        let r = self.save_restart_inner(ctx, s);
        self.cpu += thread_cpu_seconds() - cpu0;
        r
    }

    fn save_restart_inner(&mut self, ctx: &Context, s: &LoopState) -> Result<(), RunError> {
        if let Some(f) = &mut self.file {
            f.append_th(&self.pending).map_err(input)?;
            self.pending.clear();
            f.checkpoint().map_err(input)?;
        }
        let counters = OutputCounters {
            states: self.states.clone(),
            th_rows: self.file.as_ref().map(|f| f.th_rows).unwrap_or(0),
            next_th: self.history.next,
            next_anim: self.next_anim,
        };
        restart::save(ctx, &self.rst_path, s, &counters).map_err(input)
    }

    /// Whether the end of this cycle (time `t`) writes a time-history row
    /// (which needs the velocities at t^n).
    pub fn samples_at(&self, t: f64) -> bool {
        self.file.is_some() && self.history.due(t)
    }

    /// At the end of every cycle (collective). `Some(message)` when the run
    /// stops here: the restart file is written, the message is the listing's.
    pub fn after_cycle(
        &mut self,
        ctx: &Context,
        s: &mut LoopState,
    ) -> Result<Option<String>, RunError> {
        let began = std::time::Instant::now();
        let r = self.after_cycle_inner(ctx, s);
        self.spent += began.elapsed();
        r
    }

    fn after_cycle_inner(
        &mut self,
        ctx: &Context,
        s: &mut LoopState,
    ) -> Result<Option<String>, RunError> {
        let cycle = *s.cycle;
        self.hooks.fire(self.rank, cycle);
        self.outputs(ctx, s, false)?;
        let signal = stop::requested();
        let stop_here = self.stop_after == Some(cycle);
        // The vote completed here was cast at the end of the previous cycle:
        // a signal stops every rank at the same cycle, the one after it came.
        let any_signal = self.vote.cast(signal.is_some());
        if stop_here || any_signal {
            self.save_restart(ctx, s)?;
            let why = if any_signal {
                "on a stop signal (SIGTERM/SIGINT)"
            } else {
                "as --stop-after-cycle asks"
            };
            return Ok(Some(format!(
                "     STOPPED AT CYCLE {cycle} {why}: restart with --restart {}",
                self.rst_path.display()
            )));
        }
        if self.rfile_cycles.is_some_and(|n| cycle.is_multiple_of(n)) {
            self.save_restart(ctx, s)?;
        }
        self.progress.update(*s.t, cycle, *s.dt);
        Ok(None)
    }

    /// After the loop (collective, also after a stop or an error): the last
    /// state and samples, the XDMF file; closes the run file.
    pub fn finish(&mut self, ctx: &Context, s: &mut LoopState) -> Result<(), RunError> {
        let began = std::time::Instant::now();
        let cpu0 = thread_cpu_seconds();
        let cpu_before = self.cpu;
        self.vote.complete();
        self.progress.finish();
        self.finishing = true;
        self.outputs(ctx, s, true)?;
        if let Some(f) = &mut self.file {
            f.append_th(&self.pending).map_err(input)?;
            self.pending.clear();
        }
        // Closing writes everything out.
        self.file = None;
        self.spent += began.elapsed();
        self.cpu = cpu_before + (thread_cpu_seconds() - cpu0);
        Ok(())
    }

    /// Wall time spent in the output hooks so far, in seconds (this rank).
    pub fn seconds(&self) -> f64 {
        self.spent.as_secs_f64()
    }

    /// CPU time of this rank's calling thread in the output hooks so far,
    /// in seconds.
    pub fn cpu_seconds(&self) -> f64 {
        self.cpu
    }

    /// Path of the run file.
    pub fn h5_path(&self) -> &Path {
        &self.h5_path
    }
}
