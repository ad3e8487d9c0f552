//! Section builders: one section per part used by a block's elements (built
//! once per part, in the order the parts first appear), and the section index
//! of every element. The property and material look-ups, with the refusals
//! they make, are shared with the registry, which reads the formulation
//! number from the same property.

use crate::domain::LocalElements;
use crate::element::hex8::SolidSection;
use crate::element::shell4::ShellSection;
use crate::material::{Failure, Material};
use crate::model::{MaterialSpec, Part, Property, ResolvedShell, ResolvedSolid};
use std::collections::HashMap;

/// A formulation's shell section from its property and material
/// (`ShellSection::new` for the quad, `shell3::shell3_section` for the triangle).
pub(super) type ShellSectionFn = fn(&ResolvedShell, &Material) -> Result<ShellSection, String>;
/// A formulation's solid section (`SolidSection::new`, `SolidSection::for_tetra`).
pub(super) type SolidSectionFn = fn(&ResolvedSolid, &Material) -> Result<SolidSection, String>;

pub(super) const SHELL_WITHOUT_MATERIAL: &str = "shell part without material";
pub(super) const SOLID_WITHOUT_MATERIAL: &str = "solid part without material";

/// The sections of `le`'s parts, built by `build` once per part in the order
/// the parts first appear, and each element's section index.
pub(super) fn per_part<S>(
    le: &LocalElements,
    mut build: impl FnMut(u32) -> Result<S, String>,
) -> Result<(Vec<S>, Vec<u16>), String> {
    let mut sections = Vec::new();
    let mut of_part: HashMap<u32, u16> = HashMap::new();
    let mut section = Vec::with_capacity(le.part.len());
    for &p in &le.part {
        let s = match of_part.get(&p) {
            Some(&s) => s,
            None => {
                sections.push(build(p)?);
                of_part.insert(p, (sections.len() - 1) as u16);
                (sections.len() - 1) as u16
            }
        };
        section.push(s);
    }
    Ok((sections, section))
}

/// The resolved /PROP/SHELL of a shell part.
pub(super) fn shell_property<'a>(
    part: &Part,
    props: &'a [Property],
) -> Result<&'a ResolvedShell, String> {
    Ok(
        props[part.prop.ok_or("shell part without property")? as usize]
            .shell
            .as_ref()
            .ok_or("shell part without a shell property")?,
    )
}

/// The resolved /PROP/SOLID of a solid part.
pub(super) fn solid_property<'a>(
    part: &Part,
    props: &'a [Property],
) -> Result<&'a ResolvedSolid, String> {
    Ok(
        props[part.prop.ok_or("solid part without property")? as usize]
            .solid
            .as_ref()
            .ok_or("solid part without a solid property")?,
    )
}

/// The material card of a part; `missing` is the refusal when it has none.
pub(super) fn part_material<'a>(
    part: &Part,
    mats: &'a [MaterialSpec],
    missing: &'static str,
) -> Result<&'a MaterialSpec, String> {
    Ok(&mats[part.mat.ok_or(missing)? as usize])
}

/// Shell sections per part (built once per part used) by the formulation's
/// section constructor.
pub(super) fn shell_sections(
    le: &LocalElements,
    parts: &[Part],
    props: &[Property],
    mats: &[MaterialSpec],
    new_section: ShellSectionFn,
) -> Result<(Vec<ShellSection>, Vec<u16>), String> {
    per_part(le, |p| {
        let part = &parts[p as usize];
        let prop = shell_property(part, props)?;
        let card = part_material(part, mats, SHELL_WITHOUT_MATERIAL)?;
        let mut section = new_section(prop, &Material::from_card(card))?;
        section.failure = Failure::of_material(&card.failures)?;
        if let (Some(f), Some(spec)) = (&section.failure, card.failures.first()) {
            if section.material.brittle().is_some() {
                return Err(format!(
                    "{}: a failure model on /MAT/LAW27 is not computed (the law cracks and deletes by itself)",
                    spec.loc
                ));
            }
            if let Some(why) = f.shell_refusal() {
                return Err(format!("{}: {why}", spec.loc));
            }
            if section.global {
                return Err(format!(
                    "{}: a failure model on a shell section with global integration (N = 0) is not computed; give N >= 1 integration points",
                    spec.loc
                ));
            }
        }
        Ok(section)
    })
}

/// Solid sections per part (built once per part used) by the formulation's
/// section constructor.
pub(super) fn solid_sections(
    le: &LocalElements,
    parts: &[Part],
    props: &[Property],
    mats: &[MaterialSpec],
    new_section: SolidSectionFn,
) -> Result<(Vec<SolidSection>, Vec<u16>), String> {
    per_part(le, |p| {
        let part = &parts[p as usize];
        let prop = solid_property(part, props)?;
        let card = part_material(part, mats, SOLID_WITHOUT_MATERIAL)?;
        let material = Material::from_card(card);
        if let Some(why) = material.solid_refusal() {
            return Err(format!("{}: {why}", card.loc));
        }
        let mut section = new_section(prop, &material)?;
        match (section.ortho.is_some(), material.composite3d().is_some()) {
            (true, false) => return Err(format!(
                "/MAT/LAW{} on /PROP/TYPE6 (SOL_ORTH): an isotropic law kept in the element's frame is not computed yet (the engine computes /MAT/LAW12 there)",
                material.law_number()
            )),
            (false, true) => return Err(format!(
                "{}: /MAT/LAW12 needs the orthotropic directions of /PROP/TYPE6 (SOL_ORTH)",
                card.loc
            )),
            _ => {}
        }
        section.failure = Failure::of_material(&card.failures)?;
        if let (Some(f), Some(spec)) = (&section.failure, card.failures.first()) {
            if let Some(why) = f.solid_refusal() {
                return Err(format!("{}: {why}", spec.loc));
            }
        }
        Ok(section)
    })
}
