//! /NODE and the element keywords (/SHELL, /SH3N, /BRICK, /TETRA4, /SPRING,
//! /TRUSS, /BEAM). Elements keep their part id from the keyword line.

use super::fields::Cards;
use super::source::Block;
use super::{header_id, Deck, Id};
use crate::model::{ElementKind, InputResult, Loc};
use serde::{Deserialize, Serialize};

/// `/NODE`: node_ID (1-10), X (11-30), Y (31-50), Z (51-70).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct NodeCard {
    pub id: Id,
    pub x: [f64; 3],
    pub loc: Loc,
}

/// One element card. `nodes` holds node ids; 0 = not given (a /BEAM or
/// /SPRING orientation node, or a /SHELL whose 4th node repeats the 3rd).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ElementCard {
    pub id: Id,
    pub part: Id,
    pub nodes: Vec<Id>,
    /// /SHELL, /SH3N: orientation angle Phi (degrees); /BEAM, /SPRING: 0.
    pub phi: f64,
    /// /SHELL, /SH3N: element thickness (0 = from the property).
    pub thick: f64,
    pub loc: Loc,
}

/// All element cards, one list per kind.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Elements {
    pub shell4: Vec<ElementCard>,
    pub shell3: Vec<ElementCard>,
    pub brick8: Vec<ElementCard>,
    pub tetra4: Vec<ElementCard>,
    pub spring: Vec<ElementCard>,
    pub truss: Vec<ElementCard>,
    pub beam: Vec<ElementCard>,
}

impl Elements {
    pub fn of_kind(&self, k: ElementKind) -> &Vec<ElementCard> {
        match k {
            ElementKind::Shell4 => &self.shell4,
            ElementKind::Shell3 => &self.shell3,
            ElementKind::Brick8 => &self.brick8,
            ElementKind::Tetra4 => &self.tetra4,
            ElementKind::Spring => &self.spring,
            ElementKind::Truss => &self.truss,
            ElementKind::Beam => &self.beam,
        }
    }
    fn of_kind_mut(&mut self, k: ElementKind) -> &mut Vec<ElementCard> {
        match k {
            ElementKind::Shell4 => &mut self.shell4,
            ElementKind::Shell3 => &mut self.shell3,
            ElementKind::Brick8 => &mut self.brick8,
            ElementKind::Tetra4 => &mut self.tetra4,
            ElementKind::Spring => &mut self.spring,
            ElementKind::Truss => &mut self.truss,
            ElementKind::Beam => &mut self.beam,
        }
    }
    /// The kinds in the model's order.
    pub const KINDS: [ElementKind; 7] = ElementKind::ALL;
}

/// `/NODE` (and `/NODE/unit_ID`): one node a line until the next keyword.
///
/// A node numbered 0 is left out with a warning. OpenRadioss reads it (QA's
/// RESSORT_kjoint2 has one; its starter listing prints node 0 among the
/// coordinates), but 0 in a node field means "no node" throughout the
/// reference guide (an optional node, a group list's 0 entries), so nothing
/// can name that node: it joins no element, group or condition, has no mass,
/// and moves nothing.
pub(super) fn parse_nodes(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let mut cards = Cards::new(block);
    deck.nodes.reserve(block.lines.len());
    while let Some(c) = cards.next_nonblank() {
        if c.int_opt(1, 10, "node_ID")? == Some(0) {
            deck.warnings.push(crate::model::Warning {
                loc: c.loc(),
                keyword: block.header.clone(),
                message: "node_ID 0 is left out: 0 means 'no node' in every node field, so no element, group or condition can name it".into(),
            });
            continue;
        }
        let id = c.id(1, "node_ID")?;
        let x = c.real(11, "X", 0.0)?;
        let y = c.real(31, "Y", 0.0)?;
        let z = c.real(51, "Z", 0.0)?;
        deck.nodes.push(NodeCard {
            id,
            x: [x, y, z],
            loc: c.loc(),
        });
    }
    Ok(())
}

/// Element lists. Layouts (10-column fields):
/// - `/SHELL/part_ID`: shell_ID 1-10, node_ID1..4 11-50, Phi 51-70, Thick 71-90
///   (as HyperCrash writes them, e.g. TWISBEAM's include file).
/// - `/SH3N/part_ID`: sh3n_ID 1-10, node_ID1..3 11-40, Phi 51-70, Thick 71-90.
/// - `/BRICK/part_ID`: brick_ID, node_ID1..8 (11-90).
/// - `/TETRA4/part_ID`: tetra_ID, node_ID1..4.
/// - `/SPRING/part_ID`: spring_ID, node_ID1, node_ID2, (node_ID3 for TYPE13 orientation, 41-50).
/// - `/TRUSS/part_ID`: truss_ID, node_ID1, node_ID2.
/// - `/BEAM/part_ID`: beam_ID, node_ID1, node_ID2, node_ID3 (orientation; 0 = none).
pub(super) fn parse_elements(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let kind = match block.parts[0].as_str() {
        "SHELL" => ElementKind::Shell4,
        "SH3N" => ElementKind::Shell3,
        "BRICK" => ElementKind::Brick8,
        "TETRA4" => ElementKind::Tetra4,
        "SPRING" => ElementKind::Spring,
        "TRUSS" => ElementKind::Truss,
        _ => ElementKind::Beam,
    };
    let part = header_id(block, 1, "part_ID")?;
    let mut cards = Cards::new(block);
    let list = deck.elements.of_kind_mut(kind);
    list.reserve(block.lines.len());
    let names = [
        "node_ID1", "node_ID2", "node_ID3", "node_ID4", "node_ID5", "node_ID6", "node_ID7",
        "node_ID8",
    ];
    while let Some(c) = cards.next_nonblank() {
        let id = c.id(1, "elem_ID")?;
        let mut nodes = Vec::with_capacity(kind.nodes());
        for (k, name) in names.iter().enumerate().take(kind.nodes()) {
            let col = 11 + 10 * k;
            let optional = matches!(kind, ElementKind::Beam if k == 2)
                || matches!(kind, ElementKind::Shell4 if k == 3);
            let n = if optional {
                c.id_opt(col, name)?
            } else {
                c.id(col, name)?
            };
            nodes.push(n);
        }
        let (phi, thick) = match kind {
            ElementKind::Shell4 | ElementKind::Shell3 => {
                let phi = c.real(51, "Phi", 0.0)?;
                let thick = c.real(71, "Thick", 0.0)?;
                if thick < 0.0 {
                    return Err(c.err(
                        "Thick",
                        format!("{thick}: element thickness must be >= 0 (0 = property thickness)"),
                    ));
                }
                (phi, thick)
            }
            _ => (0.0, 0.0),
        };
        // A /SHELL whose 4th node is blank or repeats the 3rd is a triangle
        // written as a degenerate quad; keep it as a 4-node card with n4 = n3
        // (Radioss counts it among the 4-node shells).
        if kind == ElementKind::Shell4 && nodes[3] == 0 {
            nodes[3] = nodes[2];
        }
        list.push(super::ElementCard {
            id,
            part,
            nodes,
            phi,
            thick,
            loc: c.loc(),
        });
    }
    Ok(())
}
