//! The run's CSV files (rank 0 writes; every rank takes part in the
//! gathers): `--final-state`, `--final-elements`, `--energies`, `--history`.

use super::setup::{Ctx, State};
use crate::error::RunError;
use std::path::Path;

fn write(path: &Path, what: &str, s: String) -> Result<(), RunError> {
    std::fs::write(path, s)
        .map_err(|e| RunError::Input(format!("{}: cannot write {what}: {e}", path.display())))
}

/// Every CSV file the options ask for.
pub(super) fn write_all(cx: &Ctx, s: &State) -> Result<(), RunError> {
    let opts = cx.opts;
    if let Some(path) = &opts.final_state {
        final_state(cx, s, path)?;
    }
    if let Some(path) = &opts.final_elements {
        final_elements(cx, s, path)?;
    }
    if cx.world.rank() != 0 {
        return Ok(());
    }
    if let Some(path) = &opts.energies {
        write(path, "the energies", energies_csv(&s.energy_rows))?;
    }
    if let Some(path) = &opts.history {
        write(path, "the history", history_csv(cx, &s.history))?;
    }
    Ok(())
}

/// One CSV row per node in global id order: id, x, y, z, vx, vy, vz, vrx, vry, vrz (17 significant digits).
fn final_state(cx: &Ctx, s: &State, path: &Path) -> Result<(), RunError> {
    let (x, v, vr) = (&s.x, &s.v, &s.vr);
    let mine: Vec<(u32, [f64; 9])> = (0..x.len())
        .filter(|&l| cx.owned[l])
        .map(|l| {
            (
                cx.sd.node_global[l],
                [
                    x[l][0], x[l][1], x[l][2], v[l][0], v[l][1], v[l][2], vr[l][0], vr[l][1],
                    vr[l][2],
                ],
            )
        })
        .collect();
    let all = cx.world.allgather(&mine);
    if cx.world.rank() != 0 {
        return Ok(());
    }
    let mut rows: Vec<(u32, [f64; 9])> = all.into_iter().flatten().collect();
    rows.sort_by_key(|r| r.0);
    let mut out = String::from("id,x,y,z,vx,vy,vz,vrx,vry,vrz\n");
    for (gn, vals) in rows {
        out.push_str(&cx.g.node_ids[gn as usize].to_string());
        for val in vals {
            out.push_str(&format!(",{val:.16e}"));
        }
        out.push('\n');
    }
    write(path, "the final state", out)
}

/// One CSV row per element in global order (kind, then id): mean membrane
/// stress over the integration points (shells: local frame sxx, syy, sxy;
/// solids: sxx, syy, sxy; springs: the force in sxx), largest plastic strain,
/// thickness, internal energy (with hourglass), deleted flag.
fn final_elements(cx: &Ctx, s: &State, path: &Path) -> Result<(), RunError> {
    let mine: Vec<(usize, u32, [f64; 7])> = s
        .blocks
        .iter()
        .flat_map(|b| {
            let ki = b.kind().index();
            b.rows().into_iter().map(move |(ge, v)| (ki, ge, v))
        })
        .collect();
    let all = cx.world.allgather(&mine);
    if cx.world.rank() != 0 {
        return Ok(());
    }
    let mut rows: Vec<(usize, u32, [f64; 7])> = all.into_iter().flatten().collect();
    rows.sort_by_key(|r| (r.0, r.1));
    let mut out = String::from("kind,id,sxx,syy,sxy,eps_p,thick,eint,deleted\n");
    for (ki, ge, v) in rows {
        out.push_str(&format!(
            "{},{}",
            crate::model::ElementKind::ALL[ki].listing_name(),
            cx.g.element_ids[ki][ge as usize]
        ));
        for val in &v[..6] {
            out.push_str(&format!(",{val:.16e}"));
        }
        out.push_str(&format!(",{}\n", v[6] as u8));
    }
    write(path, "the element state", out)
}

fn energies_csv(rows: &[[f64; 9]]) -> String {
    let mut s =
        String::from("time,cycle,dt,internal,kinetic,rotational,external_work,contact,hourglass\n");
    for r in rows {
        s.push_str(&format!(
            "{:.16e},{},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e}\n",
            r[0], r[1] as u64, r[2], r[3], r[4], r[5], r[6], r[7], r[8]
        ));
    }
    s
}

fn history_csv(cx: &Ctx, history: &[(f64, Vec<[f64; 3]>)]) -> String {
    let g = cx.g;
    let mut s = String::from("time");
    for &gn in &g.th_nodes {
        let id = g.node_ids[gn as usize];
        s.push_str(&format!(",dx_{id},dy_{id},dz_{id}"));
    }
    s.push('\n');
    for (t, d) in history {
        s.push_str(&format!("{t:.16e}"));
        for u in d {
            s.push_str(&format!(",{:.16e},{:.16e},{:.16e}", u[0], u[1], u[2]));
        }
        s.push('\n');
    }
    s
}
