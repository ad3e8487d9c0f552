//! Springs and Rayleigh damping through the whole engine, against the
//! analytic answers of one mass on one spring: a step load F on a TYPE4
//! spring (stiffness K, node mass m) with /DAMP mass damping α overshoots
//! to (F/K)(1 + e^{−ζπ/√(1−ζ²)}), ζ = α/(2ω), ω = √(K/m), and settles at
//! F/K; the energy closes with the damping's work in the external work;
//! the engine file's /DAMP replaces the coefficients (α = 0: the undamped
//! overshoot 2F/K); a TYPE8 general spring along the same axis is the same
//! oscillator. 1 and 2 ranks give the same bytes.

mod common;
use common::*;
use std::path::{Path, PathBuf};

const K: f64 = 100.0;
const M_SPRING: f64 = 2.0; // half to each node: m = 1
const F: f64 = 10.0;

fn i10(v: i64) -> String {
    format!("{v:>10}")
}

fn r20(v: f64) -> String {
    format!("{v:>20}")
}

/// The property cards of a TYPE4 (`general` false) or TYPE8 spring.
fn property(general: bool) -> Vec<String> {
    let dof = |k: f64| vec![r20(k), String::new(), String::new()];
    if !general {
        let mut p = vec!["/PROP/SPRING/1".into(), "spring".into(), r20(M_SPRING)];
        p.extend(dof(K));
        return p;
    }
    let mut p = vec![
        "/PROP/SPR_GENE/1".into(),
        "general".into(),
        r20(M_SPRING) + &r20(1.0),
    ];
    for k in [K, 0.0, 0.0, 0.0, 0.0, 0.0] {
        p.extend(dof(k));
    }
    p
}

/// Writes the starter and engine decks; `alpha`: the starter /DAMP's α,
/// `engine_alpha`: the engine file's (None: no engine /DAMP).
fn write(dir: &Path, general: bool, alpha: f64, engine_alpha: Option<f64>) -> PathBuf {
    let mut d: Vec<String> = vec!["/BEGIN".into(), "SPR".into(), i10(2019) + &i10(0)];
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "m", "s"));
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "m", "s"));
    d.extend(["/NODE".into(), i10(1) + &r20(0.0) + &r20(0.0) + &r20(0.0)]);
    d.push(i10(2) + &r20(1.0) + &r20(0.0) + &r20(0.0));
    // A second, identical oscillator (nodes 3-4) so that two ranks share the model.
    d.push(i10(3) + &r20(0.0) + &r20(1.0) + &r20(0.0));
    d.push(i10(4) + &r20(1.0) + &r20(1.0) + &r20(0.0));
    d.extend(["/GRNOD/NODE/1".into(), "fixed".into(), i10(1) + &i10(3)]);
    d.extend(["/GRNOD/NODE/2".into(), "free".into(), i10(2) + &i10(4)]);
    d.extend([
        "/BCS/1".into(),
        "fixed".into(),
        "   111 111".to_string() + &i10(0) + &i10(1),
    ]);
    d.extend([
        "/BCS/2".into(),
        "x free".into(),
        "   011 111".to_string() + &i10(0) + &i10(2),
    ]);
    d.extend(["/PART/1".into(), "spring".into(), i10(1) + &i10(0)]);
    d.extend([
        "/SPRING/1".into(),
        i10(1) + &i10(1) + &i10(2),
        i10(2) + &i10(3) + &i10(4),
    ]);
    d.extend(property(general));
    d.extend([
        "/FUNCT/1".into(),
        "constant".into(),
        r20(0.0) + &r20(1.0),
        r20(100.0) + &r20(1.0),
    ]);
    d.extend(["/CLOAD/1".into(), "step".into()]);
    d.push(
        i10(1) + "         X" + &i10(0) + &i10(0) + &i10(2) + &" ".repeat(10) + &r20(1.0) + &r20(F),
    );
    d.extend(["/DAMP/1".into(), "mass damping".into()]);
    d.push(r20(alpha) + &r20(0.0) + &i10(2) + &i10(0) + &r20(0.0) + &r20(0.0));
    d.extend([
        "/TH/NODE/1".into(),
        "tip".into(),
        "DEF".into(),
        i10(2) + &i10(0),
    ]);
    d.push("/END".into());
    std::fs::create_dir_all(dir).unwrap();
    let starter = dir.join("SPR_0000.rad");
    std::fs::write(&starter, d.join("\n") + "\n").unwrap();
    let mut e = vec![
        "/RUN/SPR/1".to_string(),
        "6.0".into(),
        "/DT".into(),
        "0.1 0.0".into(),
    ];
    e.extend(["/TFILE/4".into(), "0.002".into()]);
    if let Some(a) = engine_alpha {
        e.extend(["/DAMP/1".into(), format!("{a} 0")]);
    }
    std::fs::write(dir.join("SPR_0001.rad"), e.join("\n") + "\n").unwrap();
    starter
}

struct Run {
    /// (t, x displacement of node 2).
    history: Vec<(f64, f64)>,
    /// The listing's last ERROR, in percent.
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
    ok(&out, "the spring deck runs");
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

fn peak(h: &[(f64, f64)]) -> f64 {
    h.iter().map(|&(_, u)| u).fold(f64::MIN, f64::max)
}

/// (F/K)(1 + e^{−ζπ/√(1−ζ²)}) with ζ = α/(2ω).
fn overshoot(alpha: f64) -> f64 {
    let omega = (K / (M_SPRING / 2.0)).sqrt();
    let zeta = alpha / (2.0 * omega);
    F / K * (1.0 + (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp())
}

#[test]
fn damped_spring_overshoots_and_settles_as_the_analytic_oscillator() {
    let dir = scratch("spring-damp");
    let starter = write(&dir, false, 2.0, None);
    let r = run(&dir, &starter, 1);
    let want = overshoot(2.0);
    assert!(
        (peak(&r.history) - want).abs() < 0.01 * want,
        "peak {} vs {want}",
        peak(&r.history)
    );
    let last = r.history.last().unwrap().1;
    // e^{−ζωT} = e^{−6}: within 0.3% of F/K.
    assert!((last - F / K).abs() < 0.003 * F / K, "settles at {last}");
    // The damping's work is in the external work: the balance closes.
    assert!(r.error.abs() <= 0.5, "ERROR {}%", r.error);
    // Byte-identical on 2 ranks.
    assert_eq!(run(&dir, &starter, 2).final_state, r.final_state);
}

#[test]
fn engine_damp_replaces_the_coefficients_and_a_general_spring_is_the_same_oscillator() {
    let dir = scratch("spring-damp-engine");
    let starter = write(&dir, true, 2.0, Some(0.0));
    let r = run(&dir, &starter, 1);
    // α = 0 from the engine file: the undamped overshoot 2F/K.
    let want = overshoot(0.0);
    assert!(
        (peak(&r.history) - want).abs() < 0.01 * want,
        "peak {} vs {want}",
        peak(&r.history)
    );
    assert!(r.error.abs() <= 0.5, "ERROR {}%", r.error);
    let dir = scratch("spring-damp-general");
    let starter = write(&dir, true, 4.0, None);
    let r = run(&dir, &starter, 1);
    let want = overshoot(4.0);
    assert!(
        (peak(&r.history) - want).abs() < 0.01 * want,
        "peak {} vs {want}",
        peak(&r.history)
    );
}

#[test]
fn engine_damp_without_its_starter_card_is_refused() {
    let dir = scratch("spring-damp-orphan");
    let starter = write(&dir, false, 1.0, Some(3.0));
    let engine = std::fs::read_to_string(dir.join("SPR_0001.rad")).unwrap();
    std::fs::write(
        dir.join("SPR_0001.rad"),
        engine.replace("/DAMP/1", "/DAMP/7"),
    )
    .unwrap();
    let out = crashsim(&[
        "run",
        starter.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("/DAMP/7") && err.contains("SPR_0001.rad"),
        "{err}"
    );
}
