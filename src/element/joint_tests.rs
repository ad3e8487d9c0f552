use super::*;
use crate::model::JointDof;

fn spherical(kn: f64, cr: f64) -> JointProperty {
    JointProperty {
        joint_type: 1,
        kn,
        scf: if kn == 0.0 { 1.0 } else { 10.0 },
        cr,
        sens_id: 0,
        skew_ids: [0, 0],
        free: (3..6)
            .map(|i| {
                (
                    i,
                    JointDof {
                        k: 1.0,
                        ..Default::default()
                    },
                )
            })
            .collect(),
    }
}

fn side(mass: f64, inertia: f64, arm2: f64) -> Side {
    Side {
        mass,
        inertia,
        mean_inertia: inertia,
        arm2,
    }
}

#[test]
fn automatic_stiffness_is_the_smallest_body_limit() {
    // RESSORT_kjoint2's listing: rb1 (m 156, smallest I 31200, arm 75)
    // and rb2 (m 156, I 670800) at the /DTIX bound 1.475e-3 give
    // KNN 4.9746e5 and KNR 3.4977e9.
    let sides = [
        side(156.0, 31200.0, 75.0 * 75.0),
        side(156.0, 670800.0, 0.0),
    ];
    let (knn, knr) = automatic_stiffness(&sides, 0.0, 1.475e-3, 1.0);
    assert!((knn / 4.9746e5 - 1.0).abs() < 1e-4, "{knn}");
    assert!((knr / 3.4977e9 - 1.0).abs() < 1e-4, "{knr}");
}

#[test]
fn a_stretched_spherical_joint_pulls_its_nodes_together_with_no_net_moment() {
    let j = Joint::new(
        &spherical(100.0, 0.0),
        [side(1.0, 1.0, 0.0); 2],
        0.0,
        0.0,
        |_| None,
    )
    .unwrap();
    let x0 = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
    let mut st = Joint::init(&x0);
    let x = [[0.0, 0.0, 0.0], [1.0, 0.02, 0.0]];
    let o = j.step(&x, &[[0.0; 3]; 2], 1e-3, &mut st);
    // F_y = K·0.02 = 2 on node 1 (external sense): internal −2.
    assert!((o.f[0][1] + 2.0).abs() < 1e-12 && (o.f[1][1] - 2.0).abs() < 1e-12);
    // Net moment of the internal forces and moments about the origin is 0.
    let mz = x[1][0] * o.f[1][1] - x[1][1] * o.f[1][0] + o.f[0][5] + o.f[1][5];
    assert!(mz.abs() < 1e-12, "{mz}");
    // Energy ½·K·d² for a step from 0.
    assert!((st.eint - 0.5 * 100.0 * 0.02 * 0.02).abs() < 1e-12);
}

#[test]
fn free_rotation_carries_its_own_stiffness_and_damping_is_critical_on_blocked_ones() {
    let j = Joint::new(
        &spherical(50.0, 0.1),
        [side(2.0, 3.0, 0.0); 2],
        0.0,
        0.0,
        |_| None,
    )
    .unwrap();
    let x = [[0.0; 3]; 2];
    let mut st = Joint::init(&x);
    // Spin node 2 about z for one step of 0.01: R_z = 0.01·w.
    let w = [[0.0; 3], [0.0, 0.0, 2.0]];
    let o = j.step(&x, &w, 0.01, &mut st);
    assert!((st.d[5] - 0.02).abs() < 1e-15);
    assert!((o.f[1][5] - 1.0 * 0.02).abs() < 1e-12, "{:?}", o.f);
    // Moving node 2 along x at 1: D = 0.01, rate 1 on the second step;
    // damping 0.1·√(50·1)·1 (reduced mass 2·2/4 = 1).
    let mut st = Joint::init(&x);
    j.step(&x, &[[0.0; 3]; 2], 0.01, &mut st);
    let o = j.step(&[[0.0; 3], [0.01, 0.0, 0.0]], &[[0.0; 3]; 2], 0.01, &mut st);
    let want = 50.0 * 0.01 + 0.1 * 50f64.sqrt() * 1.0;
    assert!((o.f[1][0] - want).abs() < 1e-12, "{} vs {want}", o.f[1][0]);
}

#[test]
fn what_is_not_computed_is_refused_by_name() {
    let mut p = spherical(0.0, 0.1);
    let sides = [side(1.0, 1.0, 0.0); 2];
    let e = Joint::new(&p, sides, 0.0, 0.0, |_| None).unwrap_err();
    assert!(e.contains("DTIX"), "{e}");
    p.kn = 10.0;
    p.joint_type = 2;
    let e = Joint::new(&p, sides, 0.0, 0.0, |_| None).unwrap_err();
    assert!(e.contains("Type 2 to 7"), "{e}");
    p.joint_type = 1;
    p.free[0].1.stop_plus = 0.1;
    let e = Joint::new(&p, sides, 0.0, 0.0, |_| None).unwrap_err();
    assert!(e.contains("stops"), "{e}");
}
