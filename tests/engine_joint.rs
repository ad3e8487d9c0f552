//! KJOINT2 (/PROP/TYPE45) through the whole engine, against the analytic
//! damped oscillator: a spherical joint of stiffness Kn ties body B (mass
//! m, its centre on the joint) to body A held still; a step force F on B's
//! main node stretches it. The blocked translation is a spring Kn with the
//! critical damping Cr·√(Kn·m̄), m̄ = m·m/(m + m) the reduced mass of the
//! two bodies (research note `docs/notes/kjoint2_research.md` §5), so B
//! overshoots to (F/Kn)(1 + e^{−ζπ/√(1−ζ²)}) with ζ = Cr√(m̄/m)/2 and the
//! energy balance closes. Two such pairs, so 1 and 2 ranks share the
//! model: the same bytes.

mod common;
use common::*;
use std::path::{Path, PathBuf};

const KN: f64 = 100.0;
const MASS: f64 = 1.0;
const CR: f64 = 0.1;
const F: f64 = 10.0;

fn i10(v: i64) -> String {
    format!("{v:>10}")
}

fn r20(v: f64) -> String {
    format!("{v:>20}")
}

fn node(id: i64, x: f64, y: f64) -> String {
    i10(id) + &r20(x) + &r20(y) + &r20(0.0)
}

/// A body: main node, its secondary-node group, mass and inertia on the card.
fn body(id: i64, main: i64, grnod: i64, nodes: [i64; 2]) -> Vec<String> {
    vec![
        format!("/RBODY/{id}"),
        format!("body {id}"),
        i10(main) + &i10(0) + &i10(0) + &i10(0) + &r20(MASS) + &i10(grnod) + &i10(0) + &i10(0),
        r20(1.0) + &r20(1.0) + &r20(1.0),
        r20(0.0) + &r20(0.0) + &r20(0.0),
        format!("/GRNOD/NODE/{grnod}"),
        "secondary".into(),
        i10(nodes[0]) + &i10(nodes[1]),
    ]
}

fn write(dir: &Path) -> PathBuf {
    let mut d: Vec<String> = vec!["/BEGIN".into(), "JNT".into(), i10(2017) + &i10(0)];
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "m", "s"));
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "m", "s"));
    d.push("/NODE".into());
    for (k, y) in [0.0, 5.0].iter().enumerate() {
        let o = 100 * k as i64;
        // Body A (held): main o+10 at x = −1, secondaries o+1 (the joint) and o+2.
        d.extend([
            node(o + 10, -1.0, *y),
            node(o + 1, 0.0, *y),
            node(o + 2, -2.0, *y),
        ]);
        // Body B (pulled): main o+20 on the joint, secondaries o+3 (the joint) and o+4.
        d.extend([
            node(o + 20, 0.0, *y),
            node(o + 3, 0.0, *y),
            node(o + 4, 1.0, *y),
        ]);
    }
    d.extend(body(1, 10, 1, [1, 2]));
    d.extend(body(2, 20, 2, [3, 4]));
    d.extend(body(3, 110, 3, [101, 102]));
    d.extend(body(4, 120, 4, [103, 104]));
    d.extend(["/GRNOD/NODE/5".into(), "held".into(), i10(10) + &i10(110)]);
    d.extend(["/GRNOD/NODE/6".into(), "pulled".into(), i10(20) + &i10(120)]);
    d.extend([
        "/BCS/1".into(),
        "held".into(),
        "   111 111".to_string() + &i10(0) + &i10(5),
    ]);
    d.extend(["/PART/1".into(), "joint".into(), i10(1) + &i10(0)]);
    d.extend([
        "/SPRING/1".into(),
        i10(1) + &i10(1) + &i10(3),
        i10(2) + &i10(101) + &i10(103),
    ]);
    d.extend(["/PROP/KJOINT2/1".into(), "spherical".into()]);
    d.push(i10(1) + &r20(KN) + &r20(0.0) + &r20(CR) + &i10(0) + &i10(0) + &i10(0));
    // The three free rotations: K = 0, no damping, no friction.
    for _ in 0..3 {
        d.extend([r20(0.0) + &i10(0), r20(0.0) + &i10(0), r20(0.0)]);
    }
    d.extend([
        "/FUNCT/1".into(),
        "constant".into(),
        r20(0.0) + &r20(1.0),
        r20(100.0) + &r20(1.0),
    ]);
    d.extend(["/CLOAD/1".into(), "step".into()]);
    d.push(
        i10(1) + "         X" + &i10(0) + &i10(0) + &i10(6) + &" ".repeat(10) + &r20(1.0) + &r20(F),
    );
    d.extend([
        "/TH/NODE/1".into(),
        "pulled".into(),
        "DEF".into(),
        i10(20) + &i10(0),
    ]);
    d.push("/END".into());
    std::fs::create_dir_all(dir).unwrap();
    let starter = dir.join("JNT_0000.rad");
    std::fs::write(&starter, d.join("\n") + "\n").unwrap();
    let e = ["/RUN/JNT/1", "3.0", "/DTIX", "0 1e-3", "/TFILE/4", "0.002"];
    std::fs::write(dir.join("JNT_0001.rad"), e.join("\n") + "\n").unwrap();
    starter
}

struct Run {
    history: Vec<(f64, f64)>,
    error: f64,
    final_state: Vec<u8>,
}

fn run(dir: &Path, starter: &Path, np: u32) -> Run {
    let (th, fs) = (dir.join("th.csv"), dir.join(format!("final{np}.csv")));
    let args = [
        "run",
        starter.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--history",
        th.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
    ];
    let out = if np == 1 {
        crashsim(&args)
    } else {
        mpirun(np, &args)
    };
    ok(&out, "the joint deck runs");
    let (_, rows) = read_csv(&th);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let error = stdout
        .lines()
        .filter_map(|l| l.split_whitespace().find(|w| w.ends_with('%')))
        .filter_map(|w| w.trim_end_matches('%').parse::<f64>().ok())
        .last()
        .unwrap_or(f64::NAN);
    Run {
        history: rows.iter().map(|r| (r[0], r[1])).collect(),
        error,
        final_state: std::fs::read(&fs).unwrap(),
    }
}

#[test]
fn a_spherical_joint_is_the_damped_oscillator_of_its_stiffness_and_reduced_mass() {
    let dir = scratch("kjoint2");
    let starter = write(&dir);
    let r = run(&dir, &starter, 1);
    // Body B's mass: its card MASS (the nodes have none).
    let reduced = MASS * MASS / (MASS + MASS);
    let zeta = CR * (KN * reduced).sqrt() / (2.0 * (KN * MASS).sqrt());
    let want = F / KN * (1.0 + (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp());
    let peak = r.history.iter().map(|&(_, u)| u).fold(f64::MIN, f64::max);
    assert!((peak - want).abs() < 0.01 * want, "peak {peak} vs {want}");
    // The period 2π/ω_d: the first peak at π/ω_d.
    let omega = (KN / MASS).sqrt() * (1.0 - zeta * zeta).sqrt();
    let t_peak = r.history.iter().find(|&&(_, u)| u == peak).unwrap().0;
    assert!(
        (t_peak - std::f64::consts::PI / omega).abs() < 0.01,
        "first peak at {t_peak}"
    );
    // The joint's damping is internal energy: the balance closes.
    assert!(r.error.abs() <= 0.5, "ERROR {}%", r.error);
    assert_eq!(run(&dir, &starter, 2).final_state, r.final_state);
}
