//! The points of four elements at once, where nothing but the law acts on
//! them (no failure model, no LAW27 or LAW36 extras, no global
//! integration, no membrane damping): the old stresses turned, the elastic
//! trials, the resultant sums and work run on lanes; a point that may yield
//! takes its law's return map alone ([`PointLaw::plane_stress_after_trial`]).
//! Each lane is bitwise [`points`] of its element: the same operations in
//! the same order, from the same generic helpers.

use super::*;
use crate::material::PlaneStressResult;

/// What [`points4`] gives for the four elements (as [`Points`], lane by lane).
pub(super) struct Points4 {
    pub nr: [F4; 3],
    pub mr: [F4; 3],
    pub q: [F4; 2],
    pub dezz: [f64; 4],
    pub deleted: [bool; 4],
    pub d_eint: [f64; 4],
    pub d_eplas: [f64; 4],
}

/// Whether [`points4`] computes a section's points.
fn plain(sec: &ShellSection) -> bool {
    !sec.global
        && sec.failure.is_none()
        && sec.tension.is_none()
        && sec.material.brittle().is_none()
        && sec.membrane_damping() == 0.0
}

/// [`points`] for four elements of section `sec` (`nip`-strided slots),
/// or `None`, having changed nothing, where the section is not plain or
/// there is no step (`dt` = 0).
#[allow(clippy::too_many_arguments)]
pub(super) fn points4(
    sec: &ShellSection,
    st: &mut [Shell4State],
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    nip: usize,
    r: &Rates<F4>,
    dt: f64,
    area_m: F4,
) -> Option<Points4> {
    if !plain(sec) || dt <= 0.0 {
        return None;
    }
    let n_ip = sec.n_ip;
    let t = F4::from_fn(|l| st[l].thick);
    let laws: [PointLaw; 4] =
        std::array::from_fn(|l| rate_and_law(sec, &mut st[l], &r.lane(l), dt, area_m.lane(l)).0);
    let e = |f: fn((f64, f64, f64)) -> f64| F4::from_fn(|l| f(laws[l].elastic_constants()));
    let (nu, g) = (e(|c| c.1), e(|c| c.2));
    let one = F4::splat(1.0);
    let a11 = e(|c| c.0) / (one - nu * nu);
    let (d_m, d_k, rot_old) = (r.d_m, r.d_k, r.rot_old);
    let gs = F4::splat(sec.k.gs);
    let (dg_zx, dg_yz) = (gs * (r.gxz * F4::splat(dt)), gs * (r.gyz * F4::splat(dt)));
    let rdt = F4::splat(dt);
    let (mut old, mut new) = (Sums::zero(), Sums::zero());
    let (mut dwp, mut dezz) = (F4::splat(0.0), F4::splat(0.0));
    let mut nfailed = [0usize; 4];
    for k in 0..n_ip {
        let slot = |l: usize| l * nip + k;
        let s: [F4; 5] = std::array::from_fn(|c| F4::from_fn(|l| sig[slot(l)][c]));
        let (o, ozx, oyz, turned) = turn_slot(s, rot_old, dg_yz, dg_zx);
        old.add(sec, k, o, ozx, oyz);
        // update_slots' point: Δε = (d_m + ζ t d_k)Δt, then the law.
        let z = F4::splat(sec.zeta[k]) * t;
        let d: [F4; 3] = std::array::from_fn(|c| (d_m[c] + z * d_k[c]) * rdt);
        // PointLaw::plane_stress's elastic trial.
        let tr = [
            turned[0] + a11 * (d[0] + nu * d[1]),
            turned[1] + a11 * (nu * d[0] + d[1]),
            turned[2] + g * d[2],
        ];
        let ezz_el = -nu * (d[0] + d[1]);
        let svm2 = tr[0] * tr[0] + tr[1] * tr[1] - tr[0] * tr[1] + F4::splat(3.0) * tr[2] * tr[2];
        let elastic_ezz = ezz_el / (one - nu);
        let (mut wp, mut ez) = ([0.0; 4], [0.0; 4]);
        let mut fin = [[0.0; 4]; 5];
        let (tr, turned) = (tr.map(F4::to_array), turned.map(F4::to_array));
        let (svm2, elastic_ezz, ezz_el) =
            (svm2.to_array(), elastic_ezz.to_array(), ezz_el.to_array());
        for l in 0..4 {
            let ep = &mut eps_p[slot(l)];
            let out = &mut sig[slot(l)];
            let law = &laws[l];
            let mut s3 = [tr[0][l], tr[1][l], tr[2][l]];
            let res = if law.has_failed(*ep) {
                s3 = [0.0; 3];
                PlaneStressResult {
                    failed: true,
                    ..Default::default()
                }
            } else if law.surely_elastic(svm2[l]) {
                PlaneStressResult {
                    d_ezz: elastic_ezz[l],
                    ..Default::default()
                }
            } else {
                law.plane_stress_after_trial(&mut s3, ep, ezz_el[l], sec.iplas)
            };
            if res.failed {
                *out = [0.0; 5];
                nfailed[l] += 1;
            } else {
                *out = [s3[0], s3[1], s3[2], turned[3][l], turned[4][l]];
            }
            (0..5).for_each(|c| fin[c][l] = out[c]);
            (wp[l], ez[l]) = (res.d_wplas, res.d_ezz);
        }
        let wm = F4::splat(sec.w_mem[k]);
        dwp = dwp + wm * F4::new(wp);
        dezz = dezz + wm * F4::new(ez);
        // The new sums point by point, in the order `points` takes them.
        let fin = fin.map(F4::new);
        new.add(sec, k, [fin[0], fin[1], fin[2]], fin[4], fin[3]);
    }
    let d_eint = resultant_work(t, &old, &new, r, dt) * area_m;
    let d_eplas = dwp * area_m * t;
    let first = sec.material.deletes_at_first_failed_point();
    let deleted = nfailed.map(|n| n == n_ip || (n > 0 && first));
    let (d_eint, d_eplas) = (d_eint.to_array(), d_eplas.to_array());
    for (l, s) in st.iter_mut().enumerate() {
        s.eint += d_eint[l];
        s.eplas += d_eplas[l];
        s.deleted |= deleted[l];
    }
    Some(Points4 {
        nr: new.n.map(|c| c * t),
        mr: new.m.map(|c| c * (t * t)),
        q: [new.q[0] * t, new.q[1] * t],
        dezz: dezz.to_array(),
        deleted,
        d_eint,
        d_eplas,
    })
}
