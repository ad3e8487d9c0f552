//! Four Belytschko-Tsay shells of one section in one step (issue 16's
//! batched kernel): the geometry, rates, rotations, hourglass and corner
//! forces of [`shell4_step`] run on [`F4`] lanes, one element per lane, from
//! the same generic source; the points' laws, which branch point by point,
//! run element by element. Each lane's result is bitwise the result of
//! [`shell4_step`] for that element (see `element::lanes`), so how a
//! partition groups elements never changes the answer.

use super::*;

/// Whether elements of section `sec` may go four at a time: the forms the
/// lanes compute (Ishell 1, 2, 4; large strain). Ishell 3's capped hourglass,
/// QEPH and small strain stay with [`shell4_step`].
pub fn batches(sec: &ShellSection) -> bool {
    matches!(sec.ishell, 1 | 2 | 4) && sec.ismstr != 1
}

/// One step of four elements of section `sec` (one per lane: corners `x`,
/// velocities `v`, `vr`; states `st`; their `sec.n_ip` points each at
/// `nip`-strided slots of `sig`, `eps_p`, `dmg`). Returns `None`, having
/// changed nothing, when one of them must take [`shell4_step`]: deleted, a
/// degenerate quad, or a geometry that check would refuse.
#[allow(clippy::too_many_arguments)]
pub fn shell4_step4(
    sec: &ShellSection,
    x: &[[[f64; 3]; 4]; 4],
    v: &[[[f64; 3]; 4]; 4],
    vr: &[[[f64; 3]; 4]; 4],
    dt: f64,
    st: &mut [Shell4State],
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [PointHistory],
    nip: usize,
) -> Option<[Shell4Out; 4]> {
    if !batches(sec) || st.len() != 4 || st.iter().any(|s| s.deleted || s.tri || s.geo0.is_some()) {
        return None;
    }
    let lanes = |a: &[[[f64; 3]; 4]; 4]| -> [[F4; 3]; 4] {
        let mut t = [[F4::splat(0.0); 3]; 4];
        for (i, ti) in t.iter_mut().enumerate() {
            for (k, tik) in ti.iter_mut().enumerate() {
                *tik = F4::new([a[0][i][k], a[1][i][k], a[2][i][k], a[3][i][k]]);
            }
        }
        t
    };
    let (x, v, vr) = (lanes(x), lanes(v), lanes(vr));
    let (ge, ok) = Geom::build(&x);
    if !ok {
        return None;
    }
    let gm = if dt > 0.0 {
        let (gm, ok) = Geom::build(&mid_step(&x, &v, dt));
        if !ok {
            return None;
        }
        gm
    } else {
        ge
    };
    if !dot(gm.e[2], ge.e[2]).all(|c| c > 0.0) {
        return None;
    }
    let kc = &sec.k;
    let dt_el = char_length(sec, &ge, false) / F4::splat(kc.c) * F4::splat(sec.viscmx());
    let orth = sec.ishell != 2;
    let r = Rates::new(&gm, &ge, &v, &vr, dt, orth);
    let t = F4::from_fn(|l| st[l].thick);
    let zero = F4::splat(0.0);
    let p = match points4(sec, st, sig, eps_p, nip, &r, dt, gm.area) {
        Some(p) => p,
        None => points_one_by_one(sec, st, sig, eps_p, dmg, nip, &r, dt, &gm, &ge),
    };
    let mut out = [Shell4Out::default(); 4];
    for (l, o) in out.iter_mut().enumerate() {
        *o = Shell4Out {
            dt: dt_el.lane(l),
            d_eint: p.d_eint[l],
            d_eplas: p.d_eplas[l],
            failed: p.deleted[l],
            ..Default::default()
        };
    }
    let (nr, mr, q, dezz) = (p.nr, p.mr, p.q, p.dezz);
    let mut hg = [zero; N_HG];
    for (c, h) in hg.iter_mut().enumerate() {
        *h = F4::from_fn(|l| st[l].hourglass[c]);
    }
    let (h, hg, d_ehg) = hourglass_visco(sec, &ge, t, &r, hg, dt);
    let (f, m) = corner_forces(&ge, orth, nr, mr, q, h);
    let (hg, d_ehg) = (hg.map(F4::to_array), d_ehg.to_array());
    let (f, m) = (
        f.map(|c| c.map(F4::to_array)),
        m.map(|c| c.map(F4::to_array)),
    );
    for (l, (out, s)) in out.iter_mut().zip(st.iter_mut()).enumerate() {
        if out.failed {
            continue;
        }
        for c in 0..N_HG {
            s.hourglass[c] = hg[c][l];
        }
        out.d_ehg = d_ehg[l];
        s.ehg += out.d_ehg;
        for i in 0..4 {
            for c in 0..3 {
                out.f[i][c] = f[i][c][l];
                out.m[i][c] = m[i][c][l];
            }
        }
        if sec.ithick == 1 && dt > 0.0 {
            s.thick = s.thick * (1.0 + dezz[l]);
        }
    }
    Some(out)
}

/// [`points`] of each element in turn, gathered into lanes.
#[allow(clippy::too_many_arguments)]
fn points_one_by_one(
    sec: &ShellSection,
    st: &mut [Shell4State],
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [PointHistory],
    nip: usize,
    r: &Rates<F4>,
    dt: f64,
    gm: &Geom<F4>,
    ge: &Geom<F4>,
) -> Points4 {
    let (mut nr, mut mr, mut q) = ([[0.0; 4]; 3], [[0.0; 4]; 3], [[0.0; 4]; 2]);
    let (mut dezz, mut deleted) = ([0.0; 4], [false; 4]);
    let (mut d_eint, mut d_eplas) = ([0.0; 4], [0.0; 4]);
    for l in 0..4 {
        let pts = l * nip..l * nip + sec.n_ip;
        let (am, ae) = (gm.area.lane(l), ge.area.lane(l));
        let (sg, ep, dm) = (
            &mut sig[pts.clone()],
            &mut eps_p[pts.clone()],
            &mut dmg[pts],
        );
        let p = points(sec, &mut st[l], sg, ep, dm, &r.lane(l), dt, am, ae);
        for c in 0..3 {
            nr[c][l] = p.nr[c];
            mr[c][l] = p.mr[c];
        }
        q[0][l] = p.q[0];
        q[1][l] = p.q[1];
        (dezz[l], deleted[l]) = (p.dezz, p.deleted);
        (d_eint[l], d_eplas[l]) = (p.d_eint, p.d_eplas);
    }
    Points4 {
        nr: nr.map(F4::new),
        mr: mr.map(F4::new),
        q: q.map(F4::new),
        dezz,
        deleted,
        d_eint,
        d_eplas,
    }
}

#[path = "shell4_batch_points.rs"]
mod lane_points;
use lane_points::{points4, Points4};

#[cfg(test)]
#[path = "shell4_batch_tests.rs"]
mod tests;
