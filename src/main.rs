//! The `crashsim` command line.

use clap::{Parser, Subcommand};
use crashsim::domain;
use crashsim::input::{self, InputOptions};
use crashsim::model::{InputError, Model};
use crashsim::parallel::{Comm, MpiWorld, World};
use crashsim::summary::Summary;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Exit code for bad input (deck, arguments, files).
const EXIT_INPUT: u8 = 2;

#[derive(Parser)]
#[command(
    name = "crashsim",
    version,
    about = "Distributed explicit crash solver for Radioss block-format decks"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Args)]
struct DeckArgs {
    /// Starter deck NAME_0000.rad
    deck: PathBuf,
    /// Engine file (default: NAME_0001.rad beside the starter, if present)
    #[arg(long)]
    engine: Option<PathBuf>,
    /// Unsupported keywords are errors instead of warnings
    #[arg(long)]
    strict: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Read a deck and print what it holds (counts, masses, interfaces, warnings)
    Check {
        #[command(flatten)]
        deck: DeckArgs,
        /// Print one JSON object instead of the table
        #[arg(long)]
        json: bool,
    },
    /// Partition a deck's elements over N ranks (METIS k-way) and report the quality
    Partition {
        #[command(flatten)]
        deck: DeckArgs,
        /// Number of ranks
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
        np: u32,
        #[arg(long)]
        json: bool,
    },
    /// Run a deck (alone or under mpirun): prints the cycle table and writes DIR/NAME.out
    Run {
        #[command(flatten)]
        deck: DeckArgs,
        /// Output directory (default: the current one)
        #[arg(long, default_value = ".")]
        out: PathBuf,
        /// Write the final nodal state (global id order, 17 significant digits) to this CSV file
        #[arg(long)]
        final_state: Option<PathBuf>,
        /// Write the final element state (mean membrane stress, plastic strain, thickness, energy) to this CSV file
        #[arg(long)]
        final_elements: Option<PathBuf>,
        /// Write the /TH/NODE nodes' displacements every /TFILE period to this CSV file
        #[arg(long)]
        history: Option<PathBuf>,
        /// Write the energies (internal without hourglass as the listing's I-ENERGY, kinetic, rotational, external work, contact, hourglass) at every cycle to this CSV file
        #[arg(long)]
        energies: Option<PathBuf>,
        /// Continue from a restart file DIR/NAME_rst.h5 (any number of ranks)
        #[arg(long)]
        restart: Option<PathBuf>,
        /// No progress line on stderr
        #[arg(long)]
        quiet: bool,
        /// The progress line on stderr even when it is not a terminal (under mpirun)
        #[arg(long, conflicts_with = "quiet")]
        progress: bool,
        /// Write the restart file after cycle K and stop (for tests)
        #[arg(long, hide = true)]
        stop_after_cycle: Option<u64>,
        /// Write no HDF5/XDMF run file (to measure what output costs)
        #[arg(long, hide = true)]
        no_run_file: bool,
        /// Run although the deck has keywords the engine does not compute; the listing and the run file name them
        #[arg(long)]
        skip_unsupported: bool,
        /// Stop the run (exit 3) when the listing's ERROR passes this many percent of energy created, where the engine file has no /STOP Emax (0: no limit)
        #[arg(long, default_value_t = 100.0, value_parser = percent)]
        energy_error_limit: f64,
        /// Threads per rank (default: RAYON_NUM_THREADS if set, else the cores divided by the ranks on this node)
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
        threads: Option<u32>,
    },
    /// Print the keywords crashsim reads and what it does with each (Markdown, as in the README)
    Keywords,
    /// Print what a run file DIR/NAME.h5 (or a restart file) holds
    Info {
        /// The HDF5 file written by `crashsim run`
        file: PathBuf,
    },
    /// Draw time histories of a run file into a PNG
    Plot {
        /// The run file DIR/NAME.h5
        file: PathBuf,
        /// The PNG to write
        #[arg(long)]
        out: PathBuf,
        /// energies, interfaces, parts, node:ID, or mesh[:plastic_strain|von_mises] (the deformed mesh coloured by an element value)
        #[arg(long, default_value = "energies")]
        what: String,
        /// mesh: the state to draw (its number under /states; default the last)
        #[arg(long)]
        state: Option<usize>,
        /// mesh: where it is seen from: iso, x, y, z, -x, -y, -z or a direction X,Y,Z
        #[arg(long, default_value = "iso")]
        view: String,
    },
    /// Under mpirun: rank 0 reads and partitions the deck, scatters one
    /// subdomain per rank; every rank reports what it holds and checks its
    /// shared nodes against its neighbours'
    Distribute {
        #[command(flatten)]
        deck: DeckArgs,
        #[arg(long)]
        json: bool,
    },
}

fn load(args: &DeckArgs) -> Result<Model, InputError> {
    input::load(
        &args.deck,
        &InputOptions {
            controls: args.engine.clone(),
            strict: args.strict,
        },
    )
}

/// A percentage: a finite number ≥ 0 (a trailing % allowed).
fn percent(s: &str) -> Result<f64, String> {
    match s.trim().trim_end_matches('%').parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!(
            "expected a percentage ≥ 0 (for example 100 or 50%), found '{s}'"
        )),
    }
}

fn input_error(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("crashsim: {e}");
    ExitCode::from(EXIT_INPUT)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Check { deck, json } => {
            let m = match load(&deck) {
                Ok(m) => m,
                Err(e) => return input_error(e),
            };
            let s = Summary::of(&m);
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&s).expect("summary serializes")
                );
            } else {
                print!("{}", s.text());
            }
            ExitCode::SUCCESS
        }
        Command::Partition { deck, np, json } => {
            let m = match load(&deck) {
                Ok(m) => m,
                Err(e) => return input_error(e),
            };
            let (p, r) = match domain::partition(&m, np as usize) {
                Ok(x) => x,
                Err(e) => {
                    return input_error(format!("{}: cannot partition: {e}", deck.deck.display()))
                }
            };
            if json {
                // Which ranks each interface's secondary nodes and main segments live on:
                // an interface "crosses" the cut when they span more than one rank.
                let (ptr, enodes) = domain::mesh_csr(&m);
                let mut node_ranks: Vec<Vec<u32>> = vec![Vec::new(); m.nodes.len()];
                for e in 0..ptr.len() - 1 {
                    for &nd in &enodes[ptr[e]..ptr[e + 1]] {
                        let r = &mut node_ranks[nd as usize];
                        if !r.contains(&p.part[e]) {
                            r.push(p.part[e]);
                        }
                    }
                }
                let ranks_of = |nodes: &mut dyn Iterator<Item = u32>| {
                    let mut s: Vec<u32> = nodes
                        .flat_map(|nd| node_ranks[nd as usize].clone())
                        .collect();
                    s.sort_unstable();
                    s.dedup();
                    s
                };
                let inter: Vec<serde_json::Value> = m
                    .interfaces
                    .iter()
                    .map(|i| {
                        serde_json::json!({
                            "id": i.card.id,
                            "type": i.card.type_number(),
                            "secondary_ranks": ranks_of(&mut i.secondary_nodes.iter().copied()),
                            "main_ranks": ranks_of(&mut i.main_segments.iter().flatten().chain(i.main_edges.iter().flatten()).copied()),
                        })
                    })
                    .collect();
                let v = serde_json::json!({
                    "deck": m.name, "np": np, "elements": m.n_elements(), "nodes": m.nodes.len(),
                    "edge_cut": r.edge_cut, "imbalance": r.imbalance, "per_rank": r.per_rank, "part": p.part,
                    "interfaces": inter,
                });
                println!(
                    "{}",
                    serde_json::to_string_pretty(&v).expect("report serializes")
                );
            } else {
                println!("deck {}: {} elements, {} nodes over {np} ranks (METIS k-way, shared-node dual graph)", m.name, m.n_elements(), m.nodes.len());
                println!(
                    "{:>6} {:>10} {:>10} {:>13} {:>10}",
                    "rank", "elements", "nodes", "shared nodes", "weight"
                );
                for (i, rr) in r.per_rank.iter().enumerate() {
                    println!(
                        "{i:>6} {:>10} {:>10} {:>13} {:>10}",
                        rr.elements, rr.nodes, rr.shared_nodes, rr.weight
                    );
                }
                println!(
                    "edge cut {}   load imbalance {:.2}%",
                    r.edge_cut,
                    100.0 * r.imbalance
                );
            }
            ExitCode::SUCCESS
        }
        Command::Distribute { deck, json } => distribute(&deck, json),
        Command::Info { file } => match crashsim::output::info::report(&file) {
            Ok(s) => {
                print!("{s}");
                ExitCode::SUCCESS
            }
            Err(e) => input_error(e),
        },
        Command::Plot {
            file,
            out,
            what,
            state,
            view,
        } => plot(&file, &out, &what, state, &view),
        Command::Keywords => {
            print!("{}", crashsim::input::supported_keywords());
            ExitCode::SUCCESS
        }
        Command::Run {
            deck,
            out,
            final_state,
            final_elements,
            history,
            energies,
            restart,
            quiet,
            progress,
            stop_after_cycle,
            no_run_file,
            skip_unsupported,
            energy_error_limit,
            threads,
        } => {
            let Some(world) = MpiWorld::init() else {
                return input_error("MPI could not be initialised");
            };
            use crashsim::parallel::threads_per_rank as tpr;
            let env = std::env::var("RAYON_NUM_THREADS").ok();
            let choice = tpr::choose(
                threads.map(|n| n as usize),
                env.as_deref(),
                tpr::cores(),
                world.ranks_on_this_node(),
            );
            if let Err(e) = tpr::apply(choice) {
                return input_error(e);
            }
            if !no_run_file || restart.is_some() {
                crashsim::output::h5::warm_up();
            }
            let opts = crashsim::solver::RunOptions {
                deck: deck.deck,
                engine: deck.engine,
                out_dir: out,
                final_state,
                final_elements,
                history,
                energies,
                strict: deck.strict,
                skip_unsupported,
                energy_error_limit,
                output: crashsim::output::OutputOptions {
                    restart,
                    quiet,
                    progress,
                    stop_after_cycle,
                    no_run_file,
                },
            };
            let result = crashsim::solver::run(&world, &opts);
            // Not before the library is set up: the process ends soon.
            crashsim::output::h5::ready();
            match result {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    if world.rank() == 0 {
                        eprintln!("crashsim: {}", e.message());
                    }
                    ExitCode::from(e.exit_code())
                }
            }
        }
    }
}

/// `crashsim plot`: time histories, or the mesh view of one state.
fn plot(file: &Path, out: &Path, what: &str, state: Option<usize>, view: &str) -> ExitCode {
    use crashsim::output::{mesh_view, plot};
    let what = match what.parse::<plot::What>() {
        Ok(w) => w,
        Err(e) => return input_error(format!("--what {e}")),
    };
    let view = match view.parse::<mesh_view::View>() {
        Ok(v) => v,
        Err(e) => return input_error(format!("--view {e}")),
    };
    let plot::What::Mesh(field) = what else {
        return match plot::plot(file, out, &what) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => input_error(e),
        };
    };
    match mesh_view::render(file, out, field, state, view) {
        Ok(m) => {
            println!(
                "{}: state {} (t = {:.6e}, cycle {}), {} faces, {} from {:.4e} to {:.4e}",
                out.display(),
                m.state,
                m.time,
                m.cycle,
                m.faces,
                field.dataset(),
                m.lo,
                m.hi
            );
            ExitCode::SUCCESS
        }
        Err(e) => input_error(e),
    }
}

fn distribute(args: &DeckArgs, json: bool) -> ExitCode {
    let Some(mpi) = MpiWorld::init() else {
        return input_error("MPI could not be initialised");
    };
    let world: &World = &mpi;
    let rank = world.rank();
    let size = world.size();
    // Rank 0 reads, builds and partitions; the others never parse text.
    let (parts, total) = if rank == 0 {
        match prepare(&args.deck, args, size) {
            Ok((p, t)) => (Some(p), Some(t)),
            Err(e) => {
                eprintln!("crashsim: {e}");
                world.abort(EXIT_INPUT as i32);
            }
        }
    } else {
        (None, None)
    };
    let totals: [u64; 2] = match world.broadcast(total.as_ref()) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("crashsim: rank {rank}: {e}");
            world.abort(3);
        }
    };
    let sd = match world.scatter(parts) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("crashsim: rank {rank}: {e}");
            world.abort(3);
        }
    };
    // Check the shared-node lists against the neighbours' (by global index).
    let ranks: Vec<u32> = sd.shared.iter().map(|s| s.rank).collect();
    let send: Vec<Vec<u64>> = sd
        .shared
        .iter()
        .map(|s| {
            s.nodes
                .iter()
                .map(|&l| sd.node_global[l as usize] as u64)
                .collect()
        })
        .collect();
    let got = world.exchange_with_neighbours(&ranks, &send);
    let agree = send == got;
    let line = serde_json::json!({
        "rank": rank, "nranks": size, "elements": sd.n_elements(), "nodes": sd.x.len(),
        "shared_nodes": sd.n_shared_nodes(), "neighbours": ranks, "shared_agree": agree,
        "mass": sd.mass.iter().sum::<f64>(), "total_elements": totals[0], "total_nodes": totals[1],
    })
    .to_string();
    if let Some(lines) = world.gather_strings(&line) {
        for l in lines {
            if json {
                println!("{l}");
            } else {
                let v: serde_json::Value = serde_json::from_str(&l).unwrap_or_default();
                println!("rank {} of {}: {} elements, {} nodes, {} shared with ranks {}, shared lists agree: {}", v["rank"], v["nranks"], v["elements"], v["nodes"], v["shared_nodes"], v["neighbours"], v["shared_agree"]);
            }
        }
    }
    world.barrier();
    if agree {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(3)
    }
}

fn prepare(
    path: &Path,
    args: &DeckArgs,
    size: u32,
) -> Result<(Vec<domain::Subdomain>, [u64; 2]), String> {
    let m = load(args).map_err(|e| e.to_string())?;
    let (p, _) = domain::partition(&m, size as usize)
        .map_err(|e| format!("{}: cannot partition: {e}", path.display()))?;
    Ok((
        domain::split(&m, &p.part, size as usize),
        [m.n_elements() as u64, m.nodes.len() as u64],
    ))
}
