//! Run controls (keyword manual volume I: "*CONTROL_TERMINATION",
//! "*CONTROL_TIMESTEP", "*DATABASE_BINARY_D3PLOT", "*TITLE"): they fill
//! the run controls a Radioss deck takes from its engine file.

use super::card::Cards;
use super::source::Block;
use super::Ctx;
use crate::model::{Engine, InputResult, RunSpec};

/// The run controls, made on the first control keyword.
fn engine<'a>(ctx: &'a mut Ctx, b: &Block) -> &'a mut Engine {
    ctx.deck.engine.get_or_insert_with(|| Engine {
        loc: b.loc.clone(),
        ..Engine::default()
    })
}

/// `*TITLE`: the title line.
pub fn title(_b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let std = cards.standard();
    if let Some(c) = cards.next_opt(std) {
        ctx.deck.title = c.title();
    }
    Ok(())
}

/// ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL.
pub fn termination(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let std = cards.standard();
    let c = cards.next(std, "the card ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL")?;
    let tstop = c.real(0, "ENDTIM", 0.0)?;
    if tstop <= 0.0 {
        return Err(c.err("ENDTIM", format!("{tstop}: expected the end time > 0")));
    }
    // ENDMAS (a mass-scaling limit) changes nothing: mass scaling
    // (*CONTROL_TIMESTEP DT2MS) is refused, so the mass never grows.
    let fields = [(1, "ENDCYC"), (2, "DTMIN"), (3, "ENDENG"), (5, "NOSOL")];
    ctx.refuse_given(&c, &kw, &fields, "", false)?;
    let name = ctx
        .deck
        .begin
        .as_ref()
        .map(|g| g.run_name.clone())
        .unwrap_or_default();
    engine(ctx, b).run = Some(RunSpec {
        name,
        number: 1,
        restart_letter: None,
        tstop,
        loc: c.loc(),
    });
    Ok(())
}

/// DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST: the scale factor
/// TSSFAC (0 → 0.9) and the first step DTINIT; the others (mass scaling,
/// step limits and curves) are refused by name.
pub fn timestep(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let std = cards.standard();
    let c = cards.next(
        std,
        "the card DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST",
    )?;
    let dtinit = c.real(0, "DTINIT", 0.0)?;
    let tssfac = c.real(1, "TSSFAC", 0.9)?;
    if !(0.0..=1.0).contains(&tssfac) {
        return Err(c.err(
            "TSSFAC",
            format!("{tssfac}: expected a scale factor from 0 to 1"),
        ));
    }
    let fields = [
        (2, "ISDO"),
        (3, "TSLIMT"),
        (4, "DT2MS"),
        (5, "LCTM"),
        (7, "MS1ST"),
    ];
    ctx.refuse_given(&c, &kw, &fields, "", false)?;
    let e = engine(ctx, b);
    e.dt_scale = if tssfac == 0.0 { 0.9 } else { tssfac };
    if dtinit < 0.0 {
        return Err(c.err(
            "DTINIT",
            format!("{dtinit}: expected a first time step >= 0"),
        ));
    }
    e.dtix.0 = dtinit;
    Ok(())
}

/// `*DATABASE_BINARY_D3PLOT`: DT, the period of the run file's states.
pub fn d3plot(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let std = cards.standard();
    let c = cards.next(std, "the card DT LCDT BEAM NPLTC PSETID")?;
    let dt = c.real(0, "DT", 0.0)?;
    if dt < 0.0 {
        return Err(c.err("DT", format!("{dt}: expected a period >= 0")));
    }
    if dt > 0.0 {
        engine(ctx, b).anim_period = Some(dt);
    }
    Ok(())
}
