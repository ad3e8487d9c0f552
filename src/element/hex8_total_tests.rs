//! The total-strain brick: exact F for linear fields (patch test),
//! objectivity, the stored energy of simple shear, the time step.

use super::*;
use crate::model::{MaterialLaw, MaterialSpec, ViscoHyperelastic};

/// LAW62 of the QA deck (two Ogden terms), optionally without its Prony series.
pub(crate) fn material(viscous: bool) -> Material {
    let (gamma, tau) = if viscous {
        (vec![0.34391, 0.10785], vec![46.2, 1.42e4])
    } else {
        (vec![], vec![])
    };
    Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 5.5e-8,
        rho_ref: 0.0,
        e: 2.0 * 6.9239e-5 * 1.2,
        nu: 0.2,
        law: MaterialLaw::ViscoHyperelastic(ViscoHyperelastic {
            mu: vec![0.069119e-3, 12.0126e-8],
            alpha: vec![30.4979, -3.6961],
            gamma,
            tau,
            mu_max: 1e20,
            flag_visc: 0,
        }),
        failures: Vec::new(),
        loc: Default::default(),
    })
}

fn section(viscous: bool, qa: f64, qb: f64, h: f64) -> SolidSection {
    let mut r = crate::element::hex8::tests::resolved(1, qa, qb, h);
    r.ismstr = 10;
    total_section(&r, &material(viscous)).unwrap()
}

fn cube(size: [f64; 3]) -> [[f64; 3]; 8] {
    let n = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ];
    n.map(|p| [p[0] * size[0], p[1] * size[1], p[2] * size[2]])
}

fn distorted() -> [[f64; 3]; 8] {
    let d = [
        [0.05, -0.02, 0.03],
        [0.10, 0.04, -0.05],
        [-0.07, 0.12, 0.02],
        [0.03, -0.06, 0.08],
        [-0.04, 0.09, -0.03],
        [0.06, -0.08, 0.11],
        [0.15, 0.05, -0.09],
        [-0.02, 0.07, 0.04],
    ];
    let mut x = cube([1.3, 0.9, 1.1]);
    for a in 0..8 {
        for k in 0..3 {
            x[a][k] += d[a][k];
        }
    }
    x
}

fn map(h: &[[f64; 3]; 3], x: &[[f64; 3]; 8]) -> [[f64; 3]; 8] {
    x.map(|p| std::array::from_fn(|i| p[i] + (0..3).map(|j| h[i][j] * p[j]).sum::<f64>()))
}

#[test]
fn a_linear_field_gives_its_exact_deformation_on_a_distorted_brick() {
    let h = [[0.02, 0.05, -0.01], [0.03, -0.04, 0.02], [0.01, 0.06, 0.03]];
    let x0 = distorted();
    let x = map(&h, &x0);
    let e = left_strain(&x, &x0);
    // B − I of F = I + H.
    let f = |i: usize, j: usize| h[i][j] + if i == j { 1.0 } else { 0.0 };
    let b = |i: usize, j: usize| (0..3).map(|k| f(i, k) * f(j, k)).sum::<f64>();
    let want = [
        b(0, 0) - 1.0,
        b(1, 1) - 1.0,
        b(2, 2) - 1.0,
        b(0, 1),
        b(1, 2),
        b(2, 0),
    ];
    for k in 0..6 {
        assert!((e[k] - want[k]).abs() < 1e-14, "{e:?} vs {want:?}");
    }
    // The corner forces of the uniform stress balance.
    let sec = section(false, 0.0, 0.0, 0.0);
    let mut st = hex8_total_init(&sec, &x0);
    let out = hex8_total_step(&sec, &x, &[[0.0; 3]; 8], 1e-3, &mut st);
    let law = sec.material.visco_hyperelastic().unwrap();
    let exact = law.stress(&want, 1e-3, &mut []).sig;
    let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..6 {
        assert!(
            (st.sig[k] - exact[k]).abs() < 1e-10 * scale,
            "{:?} vs {exact:?}",
            st.sig
        );
    }
    for k in 0..3 {
        let s: f64 = out.f.iter().map(|f| f[k]).sum();
        assert!(s.abs() < 1e-12 * st.sig.iter().fold(0.0f64, |m, v| m.max(v.abs())));
    }
}

#[test]
fn a_rigid_rotation_rotates_the_stress() {
    let sec = section(false, 0.0, 0.0, 0.0);
    let x0 = distorted();
    let h = [[0.02, 0.0, 0.08], [0.0, 0.01, 0.0], [0.0, 0.0, -0.03]];
    let sheared = map(&h, &x0);
    let mut st = hex8_total_init(&sec, &x0);
    hex8_total_step(&sec, &sheared, &[[0.0; 3]; 8], 1e-3, &mut st);
    let before = st.sig;
    let th = 0.7f64;
    let r = [
        [th.cos(), 0.0, th.sin()],
        [0.0, 1.0, 0.0],
        [-th.sin(), 0.0, th.cos()],
    ];
    let turned = sheared.map(|p| std::array::from_fn(|i| (0..3).map(|j| r[i][j] * p[j]).sum()));
    hex8_total_step(&sec, &turned, &[[0.0; 3]; 8], 1e-3, &mut st);
    let want = crate::element::hex8::rotate_voigt(&r, &before);
    let scale = before.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..6 {
        assert!(
            (st.sig[k] - want[k]).abs() < 1e-10 * scale,
            "{:?} vs {want:?}",
            st.sig
        );
    }
}

/// Slow simple shear to γ = 0.2 in many steps: the internal energy is the
/// stored energy W·V₀, W = Σ(2μ_i/α_i²)(λ₁^α_i + λ₂^α_i − 2) (note §4.3).
#[test]
fn the_work_of_simple_shear_is_the_stored_energy() {
    let sec = section(false, 0.0, 0.0, 0.1);
    let x0 = cube([75.0, 75.0, 70.0]);
    let mut st = hex8_total_init(&sec, &x0);
    let (steps, g_end) = (2000, 0.2);
    let dt = 0.01;
    let mut x = x0;
    for _ in 0..steps {
        let du = g_end * 70.0 / steps as f64;
        let mut v = [[0.0; 3]; 8];
        for a in 4..8 {
            v[a][0] = du / dt;
            x[a][0] += du;
        }
        hex8_total_step(&sec, &x, &v, dt, &mut st);
    }
    let r = (1.0f64 + g_end * g_end / 4.0).sqrt();
    let (l1, l2) = (r + g_end / 2.0, r - g_end / 2.0);
    let w: f64 = [(0.069119e-3, 30.4979), (12.0126e-8, -3.6961)]
        .iter()
        .map(|(m, a): &(f64, f64)| 2.0 * m / (a * a) * (l1.powf(*a) + l2.powf(*a) - 2.0))
        .sum();
    // ν = 0.2 adds a volumetric term only through J = 1: none here.
    let want = w * 75.0 * 75.0 * 70.0;
    assert!(
        (st.eint - want).abs() < 1e-4 * want,
        "{} vs {want}",
        st.eint
    );
    assert!(
        st.ehg.abs() < 1e-12 * want,
        "a homogeneous shear has no hourglass"
    );
}

#[test]
fn the_time_step_at_rest_is_the_length_over_the_wave_speed() {
    let sec = section(true, 0.0, 0.0, 0.1);
    let x0 = cube([75.0, 75.0, 70.0]);
    let mut st = hex8_total_init(&sec, &x0);
    let out = hex8_total_step(&sec, &x0, &[[0.0; 3]; 8], 0.0, &mut st);
    // ρc² = ⅔·2G + 2G(1 + β) with β = ν/(1 − 2ν).
    let (g, beta) = (0.069119e-3 + 12.0126e-8_f64, 0.2 / 0.6);
    let c = ((4.0 / 3.0 * g + 2.0 * g * (1.0 + beta)) / 5.5e-8).sqrt();
    assert!(
        (out.dt - 70.0 / c).abs() < 1e-6 * out.dt,
        "{} vs {}",
        out.dt,
        70.0 / c
    );
    assert!((sec.c - c).abs() < 1e-9 * c, "{} vs {c}", sec.c);
}

#[test]
fn other_laws_and_formulations_are_refused_by_name() {
    let mut r = crate::element::hex8::tests::resolved(1, 0.0, 0.0, 0.1);
    r.ismstr = 10;
    let e = total_section(&r, &crate::element::hex8::tests::mat()).unwrap_err();
    assert!(
        e.contains("Ismstr = 10 (total strain) with /MAT/LAW1"),
        "{e}"
    );
    r.isolid = 24;
    let e = total_section(&r, &material(false)).unwrap_err();
    assert!(e.contains("Isolid = 24 with Ismstr = 10"), "{e}");
    r.ismstr = 4;
    r.isolid = 1;
    let e = SolidSection::new(&r, &material(false)).unwrap_err();
    assert!(
        e.contains("/MAT/LAW62 computes its stress from the total deformation"),
        "{e}"
    );
}
