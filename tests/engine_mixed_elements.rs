//! A free body made of every element kind the engine has besides quads —
//! 4-node tetrahedra, 3-node shells and a spring — with half of it launched:
//! total momentum stays what it was (to round-off) and the final state is
//! byte-identical on 1 and 2 ranks.

mod common;
use common::*;
use std::path::{Path, PathBuf};

type V3 = [f64; 3];

fn tet_volume(a: V3, b: V3, c: V3, d: V3) -> f64 {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let w = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
    (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0]))
        / 6.0
}

/// Writes the deck; returns (dir, node masses by id, initial momentum).
fn write_deck(dir: &Path) -> (Vec<(usize, f64)>, V3) {
    let (rho, e, nu) = (7.85e-6, 210.0, 0.3);
    let h = 10.0;
    let x: Vec<V3> = vec![
        [0.0, 0.0, 0.0],
        [h, 0.0, 0.0],
        [h, h, 0.0],
        [0.0, h, 0.0],
        [0.0, 0.0, h],
        [h, 0.0, h],
        [h, h, h],
        [0.0, h, h],
        [-h, 0.0, 0.0], // node 9: the spring's far end
    ];
    // Five tetrahedra filling the cube, each oriented to a positive volume.
    let mut tets = vec![
        [1, 2, 4, 5],
        [2, 3, 4, 7],
        [2, 5, 6, 7],
        [4, 5, 7, 8],
        [2, 4, 5, 7],
    ];
    let mut mass = vec![0.0f64; 10];
    for t in tets.iter_mut() {
        let p = |i: usize| x[i - 1];
        if tet_volume(p(t[0]), p(t[1]), p(t[2]), p(t[3])) < 0.0 {
            t.swap(1, 2);
        }
        let v = tet_volume(p(t[0]), p(t[1]), p(t[2]), p(t[3]));
        for &n in t.iter() {
            mass[n] += rho * v / 4.0;
        }
    }
    // Two triangles on the top face, 1 mm thick; each node takes the share
    // of its corner angle, α/π (as the Radioss starter lumps them): right
    // isosceles triangles, ½ at the right angle (6 and 8), ¼ at the others.
    let tris = [[5, 6, 7], [5, 7, 8]];
    for t in &tris {
        for (k, &n) in t.iter().enumerate() {
            let (a, b, c) = (x[n - 1], x[t[(k + 1) % 3] - 1], x[t[(k + 2) % 3] - 1]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let cos = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2])
                / ((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt()
                    * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt());
            mass[n] += rho * 1.0 * (h * h / 2.0) * cos.acos() / std::f64::consts::PI;
        }
    }
    // A spring 1-9 of mass 2e-6 (half to each node).
    let m_spring = 2e-6;
    mass[1] += m_spring / 2.0;
    mass[9] += m_spring / 2.0;
    let i10 = |v: i64| format!("{v:>10}");
    let r20 = |v: f64| format!("{v:>20}");
    let mut d: Vec<String> = vec!["/BEGIN".into(), "mixed".into(), i10(2019) + &i10(0)];
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "mm", "ms"));
    d.push(format!("{:>20}{:>20}{:>20}", "kg", "mm", "ms"));
    d.extend([
        "/MAT/LAW1/1".into(),
        "steel".into(),
        r20(rho),
        r20(e) + &r20(nu),
    ]);
    d.extend([
        "/PROP/SOLID/1".into(),
        "tets".into(),
        i10(1) + &i10(4),
        r20(0.0),
    ]);
    d.extend([
        "/PROP/SHELL/2".into(),
        "skin".into(),
        i10(1) + &i10(2),
        r20(0.0),
        i10(3) + &i10(0) + &r20(1.0),
    ]);
    d.extend([
        "/PROP/SPRING/3".into(),
        "spring".into(),
        r20(m_spring),
        r20(50.0),
    ]);
    d.extend(["/PART/1".into(), "tets".into(), i10(1) + &i10(1)]);
    d.extend(["/PART/2".into(), "skin".into(), i10(2) + &i10(1)]);
    d.extend(["/PART/3".into(), "spring".into(), i10(3) + &i10(0)]);
    d.push("/NODE".into());
    for (i, p) in x.iter().enumerate() {
        d.push(i10(i as i64 + 1) + &r20(p[0]) + &r20(p[1]) + &r20(p[2]));
    }
    d.push("/TETRA4/1".into());
    for (i, t) in tets.iter().enumerate() {
        d.push(i10(i as i64 + 1) + &t.iter().map(|&n| i10(n as i64)).collect::<String>());
    }
    d.push("/SH3N/2".into());
    for (i, t) in tris.iter().enumerate() {
        d.push(i10(i as i64 + 1) + &t.iter().map(|&n| i10(n as i64)).collect::<String>());
    }
    d.extend(["/SPRING/3".into(), i10(1) + &i10(1) + &i10(9)]);
    // Nodes 1-4 (the bottom face) start at (2, 0, 1) mm/ms, the rest at rest.
    d.extend([
        "/INIVEL/TRA/1".into(),
        "bottom".into(),
        r20(2.0) + &r20(0.0) + &r20(1.0) + &i10(1) + &i10(0),
    ]);
    d.extend([
        "/GRNOD/NODE/1".into(),
        "bottom".into(),
        i10(1) + &i10(2) + &i10(3) + &i10(4),
        "/END".into(),
    ]);
    std::fs::write(dir.join("mixed_0000.rad"), d.join("\n") + "\n").unwrap();
    std::fs::write(
        dir.join("mixed_0001.rad"),
        "/RUN/mixed/1\n0.02\n/DT\n0.5 0.0\n/PRINT/-100/55\n",
    )
    .unwrap();
    let p0 = [
        2.0 * (1..=4).map(|n| mass[n]).sum::<f64>(),
        0.0,
        (1..=4).map(|n| mass[n]).sum::<f64>(),
    ];
    ((1..=9).map(|n| (n, mass[n])).collect(), p0)
}

fn run(dir: &Path, np: u32, tag: &str) -> PathBuf {
    let fs = dir.join(format!("final-{tag}.csv"));
    let deck = dir.join("mixed_0000.rad");
    let out_dir = dir.join(tag);
    let args = [
        "run",
        deck.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
    ];
    let out = if np == 1 {
        crashsim(&args)
    } else {
        mpirun(np, &args)
    };
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    fs
}

#[test]
fn tets_triangles_and_a_spring_conserve_momentum_on_any_rank_count() {
    let dir = std::env::temp_dir().join(format!("crashsim-mixed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (masses, p0) = write_deck(&dir);
    let one = run(&dir, 1, "np1");
    let text = std::fs::read_to_string(&one).unwrap();
    let mut p = [0.0f64; 3];
    let mut changed = 0.0f64;
    for line in text.lines().skip(1) {
        let c: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let m = masses.iter().find(|(n, _)| *n == c[0] as usize).unwrap().1;
        for k in 0..3 {
            p[k] += m * c[4 + k];
        }
        if c[0] as usize >= 5 {
            changed = changed.max(c[4].abs());
        }
    }
    assert!(changed > 1e-3, "the launch reached the rest of the body");
    for k in 0..3 {
        assert!(
            (p[k] - p0[k]).abs() <= 1e-12 * p0[0],
            "momentum {k}: {} vs {}",
            p[k],
            p0[k]
        );
    }
    let two = run(&dir, 2, "np2");
    assert!(
        std::fs::read(&one).unwrap() == std::fs::read(&two).unwrap(),
        "1 and 2 ranks differ"
    );
}
