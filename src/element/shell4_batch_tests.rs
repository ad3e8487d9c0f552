//! The batch of four is bitwise the element-by-element step: every output,
//! state, stress and plastic strain, step after step, for each section form
//! the lanes compute, through plasticity, thickness change and deletion.

use super::super::tests::{elastic, jc_mat, resolved, warped_quad, Lcg};
use super::*;

/// Four elements' states and points, `nip` slots each.
#[derive(Clone)]
struct Four {
    st: Vec<Shell4State>,
    sig: Vec<[f64; 5]>,
    ep: Vec<f64>,
    dmg: Vec<PointHistory>,
}

fn bits<T: std::fmt::Debug>(a: &T) -> String {
    // `{:?}` of f64 round-trips exactly; it tells -0.0 from 0.0 and prints NaN.
    format!("{a:?}")
}

/// Runs `steps` steps of four perturbed warped quads both ways and compares;
/// returns how many failed and the largest plastic strain reached.
fn same_both_ways(sec: &ShellSection, speed: f64, steps: usize) -> (usize, f64) {
    let nip = sec.n_ip + 1; // strided like a block with a wider section
    let mut rng = Lcg(7 + sec.ishell as u64);
    let mut x: [[[f64; 3]; 4]; 4] = std::array::from_fn(|_| {
        let mut q = warped_quad();
        q.iter_mut()
            .for_each(|c| *c = std::array::from_fn(|k| c[k] + 0.3 * rng.next()));
        q
    });
    let v: [[[f64; 3]; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| rng.v3(speed)));
    let vr: [[[f64; 3]; 4]; 4] =
        std::array::from_fn(|_| std::array::from_fn(|_| rng.v3(0.02 * speed)));
    let mut one = Four {
        st: x.iter().map(|q| shell4_init(sec, q, 1.2)).collect(),
        sig: vec![[0.0; 5]; 4 * nip],
        ep: vec![0.0; 4 * nip],
        dmg: vec![[0.0; 3]; 4 * nip],
    };
    let mut four = one.clone();
    let dt = 2e-4;
    let mut failed = 0;
    for step in 0..steps {
        let h = if step == 0 { 0.0 } else { dt };
        let want: Vec<Shell4Out> = (0..4)
            .map(|l| {
                let p = l * nip..l * nip + sec.n_ip;
                shell4_step(
                    sec,
                    &x[l],
                    &v[l],
                    &vr[l],
                    h,
                    &mut one.st[l],
                    &mut one.sig[p.clone()],
                    &mut one.ep[p.clone()],
                    &mut one.dmg[p],
                )
            })
            .collect();
        let f = &mut four;
        let Some(got) = shell4_step4(
            sec, &x, &v, &vr, h, &mut f.st, &mut f.sig, &mut f.ep, &mut f.dmg, nip,
        ) else {
            // Only a deleted element sends the four back one by one.
            assert!(
                one.st.iter().any(|s| s.deleted),
                "step {step}: batch refused"
            );
            break;
        };
        assert_eq!(bits(&got.to_vec()), bits(&want), "step {step}: outputs");
        assert_eq!(bits(&f.st), bits(&one.st), "step {step}: states");
        assert_eq!(bits(&f.sig), bits(&one.sig), "step {step}: stresses");
        assert_eq!(bits(&f.ep), bits(&one.ep), "step {step}: plastic strains");
        failed = want.iter().filter(|o| o.failed).count();
        for l in 0..4 {
            for i in 0..4 {
                for k in 0..3 {
                    x[l][i][k] += dt * v[l][i][k];
                }
            }
        }
    }
    (failed, one.ep.iter().fold(0.0, |a, &b| a.max(b)))
}

fn sec(ishell: i64, n: i64, ithick: i64, m: &Material) -> ShellSection {
    let mut r = resolved(ishell, n, 0.1);
    r.ithick = ithick;
    ShellSection::new(&r, m).unwrap()
}

#[test]
fn four_at_once_equal_one_by_one() {
    let jc = jc_mat(|j| {
        j.c = 0.01;
        j.eps_dot_0 = 1e-3;
        j.fsmooth = 1;
        j.f_cut = 10.0;
    });
    for ishell in [1, 2, 4] {
        for n in [1, 3, 5] {
            same_both_ways(&sec(ishell, n, 0, &elastic()), 2.0, 40);
            let (_, ep) = same_both_ways(&sec(ishell, n, 1, &jc), 30.0, 40);
            assert!(ep > 0.01, "Ishell {ishell}, N {n}: not plastic (ε_p {ep})");
        }
    }
}

/// Sections whose points need more than the law (here global integration
/// with Ilyushin's yield condition) take the points one element at a time
/// inside the batch: still the same bits.
#[test]
fn sections_beyond_the_plain_law_are_the_same_too() {
    let jc = jc_mat(|_| {});
    for m in [elastic(), jc] {
        let s = ShellSection::build(&resolved(1, 0, 0.1), &m, N0Rule::Global).unwrap();
        assert!(s.global);
        same_both_ways(&s, 30.0, 40);
    }
}

#[test]
fn a_deleted_lane_stays_deleted_and_the_others_go_on() {
    let m = jc_mat(|j| j.eps_p_max = 0.05);
    let (failed, _) = same_both_ways(&sec(1, 3, 1, &m), 60.0, 200);
    assert!(
        failed > 0,
        "no element failed: the test needs a faster pull"
    );
}

#[test]
fn forms_the_lanes_do_not_compute_go_one_by_one() {
    let m = elastic();
    for s in [sec(3, 3, 0, &m), sec(24, 3, 0, &m)] {
        assert!(!batches(&s));
    }
    let mut small = resolved(1, 3, 0.1);
    small.ismstr = 1;
    assert!(!batches(&ShellSection::new(&small, &m).unwrap()));
    // A geometry the step would refuse: the batch changes nothing.
    let s = sec(1, 3, 0, &m);
    let mut x = [warped_quad(); 4];
    x[2][3] = x[2][1];
    x[2][2] = x[2][0];
    let mut st: Vec<Shell4State> = x.iter().map(|q| shell4_init(&s, q, 1.2)).collect();
    let before = bits(&st);
    let (mut sig, mut ep, mut dmg) = (vec![[0.0; 5]; 12], vec![0.0; 12], vec![[0.0; 3]; 12]);
    let z = [[[0.0; 3]; 4]; 4];
    let o = shell4_step4(
        &s, &x, &z, &z, 1e-4, &mut st, &mut sig, &mut ep, &mut dmg, 3,
    );
    assert!(o.is_none());
    assert_eq!(bits(&st), before);
}
