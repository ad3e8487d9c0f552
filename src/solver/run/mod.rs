//! `crashsim run`: set-up on rank 0, scatter, the explicit cycle on every rank.
//!
//! The loop is a [`setup::State`] advanced by phase functions over a fixed
//! per-rank [`setup::Ctx`], in this order each cycle:
//! `kinematics` (velocities at n+½ with every condition), `integrate` (work,
//! positions at n+1, clock), `forces` (elements, assembly, external loads,
//! contact at n+1), `time_step` (global minimum), then the listing
//! (`report`), the output hooks (`crate::output`) and, at the end, `files`.

mod damping;
mod energy;
mod files;
mod forces;
mod integrate;
mod interface_nodal_step;
mod kinematics;
mod nodal_step;
mod peak_memory;
mod prepare;
mod pressure;
mod report;
mod setup;
mod time_step;
mod watchdog;

#[cfg(test)]
mod tests;

use crate::contact::tied::TiedSystem;
pub use crate::error::RunError;
use crate::global::GlobalData;
use crate::kinematics::rigid_body::RigidBodyState;
use crate::output;
use crate::parallel::World;
use report::Report;
use setup::{Ctx, State};
use std::path::PathBuf;
use std::time::Instant;

pub struct RunOptions {
    pub deck: PathBuf,
    pub engine: Option<PathBuf>,
    pub out_dir: PathBuf,
    pub final_state: Option<PathBuf>,
    /// Per-element final state (stress, plastic strain, thickness, energy).
    pub final_elements: Option<PathBuf>,
    /// Displacements of the /TH/NODE nodes every /TFILE period.
    pub history: Option<PathBuf>,
    /// Energies at every cycle (CSV; costs reductions every cycle).
    pub energies: Option<PathBuf>,
    pub strict: bool,
    /// Run although the input has keywords the engine does not compute
    /// (the listing and the run file say which were skipped).
    pub skip_unsupported: bool,
    /// The energy watchdog's default limit on the listing's ERROR, in
    /// percent (energy created; 0: none), where the engine file has no /STOP Emax.
    pub energy_error_limit: f64,
    /// HDF5 run file, restart, progress (src/output).
    pub output: crate::output::OutputOptions,
}

/// What one rank holds after the scatter: the replicated data, its
/// subdomain, the rigid bodies at t = 0 and the listing's notes.
type Received = (
    GlobalData,
    crate::domain::Subdomain,
    Vec<RigidBodyState>,
    Vec<String>,
);

/// Rank 0 prepares; a failure there is broadcast so every rank stops together.
fn receive(world: &World, opts: &RunOptions) -> Result<Received, RunError> {
    let rank = world.rank();
    let prepared = if rank == 0 {
        Some(prepare::prepare(opts, world.size() as usize))
    } else {
        None
    };
    let status: Result<(), String> = match &prepared {
        Some(Err(e)) => Err(e.clone()),
        _ => Ok(()),
    };
    world
        .broadcast(if rank == 0 { Some(&status) } else { None })
        .map_err(RunError::Input)?
        .map_err(RunError::Input)?;
    let (g, sds, rbs, notes) = match prepared {
        Some(Ok((g, s, r, n))) => (Some(g), Some(s), Some(r), n),
        _ => (None, None, None, Vec::new()),
    };
    let g: GlobalData = world.broadcast(g.as_ref()).map_err(RunError::Input)?;
    let bodies: Vec<RigidBodyState> = world.broadcast(rbs.as_ref()).map_err(RunError::Input)?;
    let sd = world.scatter(sds).map_err(RunError::Input)?;
    Ok((g, sd, bodies, notes))
}

pub fn run(world: &World, opts: &RunOptions) -> Result<(), RunError> {
    let started = Instant::now();
    let (g, sd, bodies, notes) = receive(world, opts)?;
    let mut ties = TiedSystem::new(g.tied.clone(), &sd);
    let mut cx = setup::context(world, opts, &g, &sd, &mut ties);
    let mut s = setup::initial_state(&mut cx, ties, bodies)?;
    let cx = cx;
    let mut dog = watchdog::Watchdog::new(&cx, &s.blocks);
    let mut report = Report::open(opts, &g.name, world.rank())?;
    report.header(&cx, &notes);
    cycle_zero(&cx, &mut s, &mut report)?;
    let interfaces = interface_table(&s);
    let octx = output::Context {
        world,
        g: &g,
        sd: &sd,
        out_dir: &opts.out_dir,
        opts: &opts.output,
        interfaces: &interfaces,
    };
    let ke_of = |v: &[[f64; 3]], vr: &[[f64; 3]], b: &[RigidBodyState], w: &[[f64; 3]]| {
        energy::kinetic(&cx, v, vr, b, w)
    };
    let mut out = output::Output::start(&octx, &mut loop_state(&mut s, &ke_of))?;
    if let Some(p) = &opts.output.restart {
        // The interfaces' Idel state came with the restart file: the
        // elements it brings back deleted are known to them already.
        let _ = forces::newly_deleted(&mut s);
        s.contact_force.clone_from(&s.fcont);
        report.line(&format!(
            " restarted from {} at cycle {}, time {:e}",
            p.display(),
            s.cycle,
            s.t
        ));
    }
    let loop_started = Instant::now();
    let awake = crate::parallel::keep_awake::KeepAwake::start();
    let mut stopped: Option<String> = None;
    let result: Result<(), RunError> = loop {
        if s.t >= cx.tstop {
            break Ok(());
        }
        if let Err(e) = cycle(&cx, &mut s, &mut report, &mut dog) {
            break Err(e);
        }
        if out.samples_at(s.t) {
            ensure_at_n(&cx, &mut s);
        }
        // Output hook: histories, states, restart files, progress, stop requests.
        match out.after_cycle(&octx, &mut loop_state(&mut s, &ke_of)) {
            Ok(None) => {}
            Ok(Some(msg)) => {
                stopped = Some(msg);
                break Ok(());
            }
            Err(e) => break Err(e),
        }
    };
    drop(awake);
    // Output hook: last state and samples, XDMF (collective, also after a stop).
    ensure_at_n(&cx, &mut s);
    let result = match (result, out.finish(&octx, &mut loop_state(&mut s, &ke_of))) {
        (Ok(()), Err(e)) => Err(e),
        (r, _) => r,
    };
    let times = Times {
        elapsed: started.elapsed().as_secs_f64(),
        looped: loop_started.elapsed().as_secs_f64(),
        output: out.seconds(),
        output_cpu: out.cpu_seconds(),
    };
    final_block(&cx, &s, &mut report, (&result, stopped.as_deref()), &times);
    files::write_all(&cx, &s)?;
    result
}

/// Cycle 0: forces and time step at t = 0, the kinetic energy the balance
/// starts from, the first listing row and history sample.
fn cycle_zero(cx: &Ctx, s: &mut State, report: &mut Report) -> Result<(), RunError> {
    // Tied secondary nodes start with their main segment's motion.
    if !s.ties.is_empty() {
        s.ties.recover(cx.world, &s.x, &mut s.v, &mut s.vr, 0.0);
    }
    let mut found = forces::all_forces(cx, s, 0.0);
    found.nodal = nodal_step::nodal_steps(cx, s)?;
    found.interface_nodal = interface_nodal_step::interface_nodal_step(cx, s);
    s.step = time_step::global_step(cx, s, found)?;
    s.dt = s.step.dt;
    let (ke0, ker0) = energy::kinetic(cx, &s.v, &s.vr, &s.bodies, &s.walls.v);
    s.e0 = ke0 + ker0;
    if cx.opts.output.restart.is_none() {
        let e = energy::Energies {
            kinetic: ke0,
            rotational: ker0,
            ..Default::default()
        };
        report.row(cx, s, &e);
        // The --energies CSV starts at t = 0 too (a deck driven by an
        // imposed velocity has its kinetic energy from cycle 1 on).
        if cx.opts.energies.is_some() {
            s.energy_rows
                .push([0.0, 0.0, s.dt, 0.0, ke0, ker0, 0.0, 0.0, 0.0]);
        }
    }
    sample_history(cx, s);
    s.next_th += cx.th_period;
    s.contact_force = s.fcont.clone();
    Ok(())
}

/// One explicit cycle: velocities at n+½, positions at n+1, forces and the
/// time step there, then the listing's rows.
fn cycle(
    cx: &Ctx,
    s: &mut State,
    report: &mut Report,
    dog: &mut watchdog::Watchdog,
) -> Result<(), RunError> {
    s.at_n = None;
    let dt_v = if s.cycle == 0 {
        0.5 * s.dt
    } else {
        0.5 * (s.dt_prev + s.dt)
    };
    let on_body = kinematics::velocities(cx, s, dt_v);
    wall_on_body(cx, s, on_body)?;
    integrate::work(cx, s, dt_v);
    integrate::positions(cx, s);
    integrate::advance_clock(cx, s);
    let node = integrate::non_finite(cx, s);
    let mut found = forces::all_forces(cx, s, s.dt);
    found.node = node;
    found.nodal = nodal_step::nodal_steps(cx, s)?;
    found.interface_nodal = interface_nodal_step::interface_nodal_step(cx, s);
    report.removals(s);
    contact_samples(s);
    s.step = time_step::global_step(cx, s, found)?;
    s.dt = s.step.dt;
    if s.t >= s.next_th {
        sample_history(cx, s);
        // A period of 0 (/TFILE dT_his = 0) samples every cycle.
        while cx.th_period > 0.0 && s.next_th <= s.t {
            s.next_th += cx.th_period;
        }
    }
    let dt_min = cx.g.engine.dt_min;
    if dt_min > 0.0 && s.dt < dt_min {
        return Err(RunError::Physics(format!(
            "time step {:e} set by {} {} is below the /DT minimum {dt_min:e} at cycle {}, time {:e}",
            s.dt, s.step.what, s.step.id, s.cycle, s.t
        )));
    }
    print_cycle(cx, s, report, dog)
}

/// A rigid wall changed the velocity of a rigid body's node on some rank
/// (collective): the run stops naming the node, the wall, the cycle and the
/// time, since the wall's impulse is not passed to the body yet (the
/// body's nodes would leave its rigid motion: a wrong answer).
fn wall_on_body(cx: &Ctx, s: &State, mine: Option<(u64, u64)>) -> Result<(), RunError> {
    if cx.walls.is_empty() || cx.g.rigid_bodies.is_empty() {
        return Ok(());
    }
    // The lowest node id (then wall id) over the ranks, as the largest negative.
    let mut v = mine.map_or([f64::NEG_INFINITY; 2], |(n, w)| [-(n as f64), -(w as f64)]);
    cx.world.max_f64(&mut v[..1]);
    let mut w = if mine.is_some_and(|m| -(m.0 as f64) == v[0]) {
        v[1]
    } else {
        f64::NEG_INFINITY
    };
    cx.world.max_f64(std::slice::from_mut(&mut w));
    if v[0] == f64::NEG_INFINITY {
        return Ok(());
    }
    Err(RunError::Physics(format!(
        "rigid wall {} stops node {} of a rigid body at cycle {}, time {:e}: a rigid wall acting on a rigid body's nodes is not computed yet (its impulse is not passed to the body)",
        -w, -v[0], s.cycle, s.t
    )))
}

/// The global energies (one all-reduce), at the cycles the --energies CSV,
/// the listing or the watchdog wants them; the printed cycles' rows and
/// interface lines; the watchdog's check (its stop comes after the row).
fn print_cycle(
    cx: &Ctx,
    s: &mut State,
    report: &mut Report,
    dog: &mut watchdog::Watchdog,
) -> Result<(), RunError> {
    let print_now = s.cycle % cx.print_every == 0 || s.t >= cx.tstop;
    let wanted = cx.opts.energies.is_some() || print_now || dog.every_cycle;
    let energies_now = wanted.then(|| {
        ensure_at_n(cx, s);
        energy::global(cx, s)
    });
    if let (Some(_), Some(e)) = (&cx.opts.energies, energies_now) {
        s.energy_rows.push([
            s.t,
            s.cycle as f64,
            s.dt,
            e.internal - e.hourglass,
            e.kinetic,
            e.rotational,
            e.external_work,
            e.contact,
            e.hourglass,
        ]);
    }
    if let (true, Some(e)) = (print_now, energies_now) {
        report.row(cx, s, &e);
        report.contact_lines(cx, s);
    }
    if print_now {
        report.tied_lines(cx, s);
    }
    match energies_now {
        Some(e) => dog.check(cx, s, &e),
        None => Ok(()),
    }
}

/// The velocities at t^n of this cycle, computed once (collective).
fn ensure_at_n(cx: &Ctx, s: &mut State) {
    if s.at_n.is_none() {
        s.at_n = Some(kinematics::at_n(cx, s));
    }
}

/// Contact forces per node and per-interface samples for the outputs.
fn contact_samples(s: &mut State) {
    if s.contact.is_empty() {
        return;
    }
    s.contact_force.clone_from(&s.fcont);
    for (smp, su) in s.interface_samples.iter_mut().zip(&s.contact.sums) {
        *smp = output::InterfaceSample {
            normal: su.f_normal,
            tangential: su.f_tangent,
            energy: su.energy,
            ..Default::default()
        };
    }
}

/// The `--history` CSV: the /TH/NODE displacements now (collective).
fn sample_history(cx: &Ctx, s: &mut State) {
    if cx.opts.history.is_none() || cx.g.th_nodes.is_empty() {
        return;
    }
    let mine: Vec<(usize, [f64; 3])> = cx
        .th_local
        .iter()
        .map(|&(i, l)| {
            (
                i,
                [0, 1, 2].map(|k| s.x[l as usize][k] - cx.sd.x[l as usize][k]),
            )
        })
        .collect();
    let all = cx.world.allgather(&mine);
    let mut d = vec![[0.0; 3]; cx.g.th_nodes.len()];
    for (i, u) in all.into_iter().flatten() {
        d[i] = u;
    }
    s.history.push((s.t, d));
}

/// The interface tables of the outputs: the contact interfaces, then the tied ones (TYPE2).
fn interface_table(s: &State) -> Vec<output::InterfaceInfo> {
    s.contact
        .setup
        .interfaces
        .iter()
        .map(|i| output::InterfaceInfo {
            id: i.id,
            type_number: i.type_number,
            title: i.title.clone(),
        })
        .chain(
            s.ties
                .setup
                .interfaces
                .iter()
                .map(|i| output::InterfaceInfo {
                    id: i.id,
                    type_number: 2,
                    title: i.title.clone(),
                }),
        )
        .collect()
}

/// The loop's state by reference, for the output hooks.
fn loop_state<'s>(s: &'s mut State, kinetic: &'s output::KineticFn<'s>) -> output::LoopState<'s> {
    output::LoopState {
        t: &mut s.t,
        cycle: &mut s.cycle,
        dt: &mut s.dt,
        dt_prev: &mut s.dt_prev,
        step_what: &mut s.step.what,
        step_id: &mut s.step.id,
        x: &mut s.x,
        v: &mut s.v,
        vr: &mut s.vr,
        fint: &mut s.fint,
        fext: &mut s.fext,
        blocks: &mut s.blocks,
        bodies: &mut s.bodies,
        wall_p: &mut s.walls.p,
        wall_v: &mut s.walls.v,
        tied: &mut s.walls.tied,
        w_ext: &mut s.w_ext,
        wall_work: &mut s.wall_work,
        next_th: &mut s.next_th,
        history: &mut s.history,
        contact: &mut s.contact,
        ties: &mut s.ties,
        fcont: &mut s.fcont,
        e_contact: &mut s.e_contact,
        fixed: &mut s.fixed,
        e0: s.e0,
        wall_force: &s.walls.force,
        contact_force: &s.contact_force,
        interfaces: &s.interface_samples,
        kinetic,
        at_n: s.at_n.as_ref(),
    }
}

/// Wall and CPU times of the run for the final block.
struct Times {
    elapsed: f64,
    looped: f64,
    output: f64,
    output_cpu: f64,
}

/// The listing's final block: termination, cycles, energies, contact
/// timers, times (collective sums first: every rank takes part).
fn final_block(
    cx: &Ctx,
    s: &State,
    report: &mut Report,
    (result, stopped): (&Result<(), RunError>, Option<&str>),
    times: &Times,
) {
    let e = energy::final_breakdown(cx, s);
    // Contact timers of rank 0 per secondary node-cycle (all ranks' secondary nodes).
    let contact_timing = (!s.contact.is_empty()).then(|| {
        let mut nsec = [
            s.contact.owned_secondary() as f64,
            s.contact.candidate_count() as f64,
        ];
        let tm = s.contact.timers;
        // The largest rank's force time and candidates: the balance.
        let mut most = [tm.force_s, nsec[1]];
        cx.world.sum_f64(&mut nsec);
        cx.world.max_f64(&mut most);
        let per = |sec: f64| 1e6 * sec / (s.cycle.max(1) as f64 * nsec[0].max(1.0));
        (
            tm.sorts,
            nsec[0] as u64,
            per(tm.search_s),
            per(tm.force_s),
            per(tm.exchange_s),
            nsec[1] as u64,
            (per(most[0]), most[1] as u64),
        )
    });
    // Peak resident memory: the sum over the ranks and the largest rank.
    let peak = peak_memory::peak_resident_bytes();
    let (mut total, mut largest) = ([peak], [peak]);
    cx.world.sum_f64(&mut total);
    cx.world.max_f64(&mut largest);
    let Some(l) = &mut report.listing else {
        return;
    };
    let cycle = s.cycle;
    l.line("");
    match result {
        Ok(()) => l.line(stopped.unwrap_or("     NORMAL TERMINATION")),
        Err(e) => l.line(&format!("     ERROR TERMINATION: {}", e.message())),
    }
    l.line(&format!("     TOTAL NUMBER OF CYCLES  : {cycle:>10}"));
    if !s.contact.is_empty() {
        // The sort decision is collective: every rank sorts as often.
        l.line(&format!(
            "     CONTACT SORTS           : {:>10}",
            s.contact.timers.sorts
        ));
    }
    l.line(&format!("     ENERGIES AT THE END     : internal {:.6E} (hourglass {:.6E} included, plastic work {:.6E}), kinetic {:.6E} + rotational {:.6E}", e[0], e[1], e[2], e[3], e[4]));
    l.line(&format!(
        "                               external work {:.6E} (loads and imposed motions {:.6E}, rigid walls {:.6E}), contact energy {:.6E}",
        e[5] + e[6], e[5], e[6], e[7]
    ));
    let at_end = energy::Energies {
        internal: e[0],
        hourglass: e[1],
        external_work: e[5] + e[6],
        contact: e[7],
        kinetic: e[3],
        rotational: e[4],
    };
    l.line(&format!(
        "     ENERGY BALANCE          : ERROR {:.1}% as Radioss lists it (internal energy without hourglass + kinetic, against the initial energy + external work); the hourglass and contact energies (elastic, friction, damping) are outside it, as in Radioss: with them it closes to {:.1}%",
        100.0 * energy::error_fraction(s.e0, &at_end),
        100.0 * energy::closed_fraction(s.e0, &at_end)
    ));
    if let Some(c) = &contact_timing {
        l.line(&format!(
            "     CONTACT                 : {} sorts, {} secondary nodes, {:.4} µs search + {:.4} µs forces + {:.4} µs exchange per secondary node-cycle (rank 0); {} candidate pairs after the last sort",
            c.0, c.1, c.2, c.3, c.4, c.5
        ));
        if cx.world.size() > 1 {
            l.line(&format!(
                "                               the slowest rank: {:.4} µs forces; the most candidate pairs on one rank: {}",
                c.6 .0, c.6 .1
            ));
        }
    }
    let (elapsed, looped) = (times.elapsed, times.looped);
    l.line(&format!(
        "     ELAPSED TIME            : {elapsed:>10.3} s   (set-up {:.3} s, cycles {looped:.3} s)",
        elapsed - looped
    ));
    l.line(&format!("     OUTPUT TIME             : {:>10.3} s   (HDF5 run file, time histories, restart files; rank 0; CPU {:.4} s)", times.output, times.output_cpu));
    let elems =
        cx.g.element_ids
            .iter()
            .map(|e| e.len())
            .sum::<usize>()
            .max(1);
    l.line(&format!(
        "     TIME PER CYCLE          : {:>10.3} µs   ({:.4} µs per element-cycle)",
        1e6 * looped / cycle.max(1) as f64,
        1e6 * looped / (cycle.max(1) as f64 * elems as f64)
    ));
    let mib = |b: f64| b / (1024.0 * 1024.0);
    l.line(&format!(
        "     PEAK MEMORY             : {:>10.1} MiB resident, all ranks ({:.1} MiB on the largest; {:.0} bytes per element)",
        mib(total[0]),
        mib(largest[0]),
        total[0] / elems as f64
    ));
    l.flush();
}
