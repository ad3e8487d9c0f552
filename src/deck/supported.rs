//! What the Radioss reader and the engine do with each keyword: the table
//! `crashsim keywords` prints and the README's "What is supported" section
//! holds (generated; `tests/readme.rs` fails when the README is stale).
//!
//! Every row names headers that its test hands to the reader's dispatcher:
//! each must be read by a family parser (never sent to the keyword policy
//! as unsupported), so the table cannot claim what the reader does not
//! read. Rows the engine refuses say so; the refusal itself is by name at
//! `run` (`solver::run::prepare`, `element::blocks::registry`).

use super::keyword_policy::SAFE_TO_SKIP;

/// Which file of a deck a keyword belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum File {
    Starter,
    Engine,
}

/// One row: the keyword as a user writes it, headers that exercise it, and
/// what crashsim does with it.
pub struct Supported {
    pub file: File,
    pub keyword: &'static str,
    /// Sample headers (as in a deck, ids included) the reader must read.
    pub headers: &'static [&'static str],
    pub what: &'static str,
}

const fn s(
    keyword: &'static str,
    headers: &'static [&'static str],
    what: &'static str,
) -> Supported {
    Supported {
        file: File::Starter,
        keyword,
        headers,
        what,
    }
}

const fn e(
    keyword: &'static str,
    headers: &'static [&'static str],
    what: &'static str,
) -> Supported {
    Supported {
        file: File::Engine,
        keyword,
        headers,
        what,
    }
}

/// The table, starter keywords first, in the order of a deck.
pub const SUPPORTED: &[Supported] = &[
    s("/BEGIN", &["/BEGIN"], "run name, input version, input and working units"),
    s("/TITLE", &["/TITLE"], "the model's title"),
    s("/NODE", &["/NODE"], "nodes (a node numbered 0 is left out with a warning)"),
    s("/SHELL", &["/SHELL/1"], "4-node shells: Belytschko-Tsay, Ishell 1-4, QEPH 24 (physical hourglass stabilization) and QBAT 12 (Batoz, 2×2 points, MITC4 transverse shear, warped geometry; elastic laws, plastic laws refused by name)"),
    s("/SH3N", &["/SH3N/1"], "3-node shells: the C0 triangle, Ish3n 1 and 2 (DKT18, DKT_S3 refused)"),
    s("/BRICK", &["/BRICK/1"], "8-node bricks: Isolid 1 and 2 (one point, viscous hourglass), 14 (HA8: 2×2×2 points, assumed strain, Icpre 0/1/2); others refused"),
    s("/TETRA4", &["/TETRA4/1"], "4-node tetrahedra (Itetra4 0, 1000)"),
    s("/SPRING", &["/SPRING/1"], "springs of /PROP/TYPE4, TYPE8 and TYPE13"),
    s("/TRUSS, /BEAM", &["/TRUSS/1", "/BEAM/1"], "trusses (/PROP/TRUSS) and beams (/PROP/BEAM; the third node orients the beam at t = 0)"),
    s("/PART", &["/PART/1"], "parts: property, material, subset"),
    s("/MAT/LAW1 (/MAT/ELAST)", &["/MAT/LAW1/1", "/MAT/ELAST/1"], "linear elastic"),
    s(
        "/MAT/LAW2 (/MAT/PLAS_JOHNS)",
        &["/MAT/LAW2/1", "/MAT/PLAS_JOHNS/1"],
        "Johnson-Cook elastic-plastic, strain-rate term (ICC, Fsmooth, Fcut), EPS_p_max and SIG_max0",
    ),
    s(
        "/MAT/LAW36 (/MAT/PLAS_TAB)",
        &["/MAT/LAW36/1", "/MAT/PLAS_TAB/1"],
        "tabulated plasticity: yield curves per strain rate (Fscale, F_smooth, F_cut), Eps_p_max, the tension damage Eps_t/Eps_m/Eps_f on 4-node shells; C_hard, VP = 1, fct_IDp, Fct_IDE/CE (and the tension damage on triangles and solids) refused by name",
    ),
    s(
        "/MAT/LAW44 (/MAT/COWPER)",
        &["/MAT/LAW44/1", "/MAT/COWPER/1"],
        "Cowper-Symonds elastic-plastic: (a + b ε_p^n)(1 + (ε̇/c)^(1/p)), SIG_max0 with ICC, the total (VP 2) or deviatoric (VP 3) strain rate, Fsmooth/F_cut, EPS_p_max; Chard ignored on solids as the reference engine does (refused on shells), VP 1, fct_IDy, εt1/εt2 refused by name",
    ),
    s(
        "/MAT/LAW21 (/MAT/DPRAG)",
        &["/MAT/LAW21/1", "/MAT/DPRAG/1"],
        "Drucker-Prager for rock, concrete and soil: J2 ≤ A0 + A1 P + A2 P² capped at Amax, the pressure P(μ) from func_IDf × FscaleP with unloading along B below Mu_max, Kt in tension, the P_min cut-off (spall), P_ext; on one-point bricks and tetrahedra (other solid formulations and shells refused by name)",
    ),
    s(
        "/MAT/LAW27 (/MAT/PLAS_BRIT)",
        &["/MAT/LAW27/1", "/MAT/PLAS_BRIT/1"],
        "Johnson-Cook plasticity with brittle tension damage on 4-node shells: σ_y = (a + b ε_pⁿ)(1 + c ln ε̇/ε̇₀) capped at SIG_max0 (ICC), the Iplas 1 return, cracking on the largest principal total strain at EPS_t1 (damage growing to d_max1 by EPS_m1, tension only), the element deleted past EPS_f1, membrane damping dm (0.05 blank); direction 2 never starts, as in the reference (3-node shells, N = 0, Iplas 2, solids and a /FAIL on it refused by name)",
    ),
    s(
        "/MAT/LAW62 (/MAT/VISC_HYP)",
        &["/MAT/LAW62/1", "/MAT/VISC_HYP/1"],
        "hyper-visco-elastic Ogden-type law on the full principal stretches (N terms μ_i, α_i, Poisson's ratio ν) with a Prony series of M terms (γ_i, τ_i; Flag_Visc 0 relaxes the deviatoric stress, 1 the whole stress); on one-point bricks (Isolid 1, 2) with Ismstr = 10 (total strain from B = FFᵀ); other formulations, strain options and shells refused by name",
    ),
    s(
        "/MAT/LAW70 (/MAT/FOAM_TAB)",
        &["/MAT/LAW70/1", "/MAT/FOAM_TAB/1"],
        "tabulated visco-elastic foam on one-point bricks (Isolid 1, 2): loading curves per strain rate (linear in the total strain rate, filtered at Fcut with Fsmooth), continued with E_max past eps_max; the stress the curve's value in the direction of the elastic stress of the secant modulus, which sets the wave speed; hysteresis unloading of Iflag 3 and 4 (Shape, Hys); qa = qb = 0 on the card means no bulk viscosity, as in the reference (Iflag 0-2, unloading curves, Itens, shells and other formulations refused by name)",
    ),
    s(
        "/FAIL/JOHNSON",
        &["/FAIL/JOHNSON/1"],
        "Johnson-Cook damage (D1-D5, EPS_0, EPSF_MIN) on solids, Ifail_so 1-4; on shells refused",
    ),
    s(
        "/FAIL/TAB",
        &["/FAIL/TAB/1"],
        "tabulated failure: ε_f(η) per strain rate (linear in ε̇), element-size and temperature factors, damage exponent n and Dcrit; card layout by input version (110, 120/130); shells (Ifail_sh 1, 2, 3 with P_thickfail; element deleted at once) and solids (Ifail_so 1, 2; no size factor); Ixfem refused; D (softening) read and, as in the reference engine, not applied",
    ),
    s(
        "/FAIL/HASHIN",
        &["/FAIL/HASHIN/1"],
        "Hashin composite criteria on solids with Ifail_so 0, which the reference reports and which change nothing in the solution (Ifail_so 1, 2: stress relaxation and deletion, and shells refused by name)",
    ),
    s(
        "/MAT/LAW12 (/MAT/3D_COMP)",
        &["/MAT/LAW12/1", "/MAT/3D_COMP/1"],
        "orthotropic solid composite on /PROP/TYPE6 bricks: E11, E22, E33, nu, G (0 allowed), tension damage per direction (sigma_t, DELTA), Tsai-Wu plasticity with work hardening 1 + B Wp^n to fmax (the element deleted at fmax); internal energy without the bulk viscosity's work, as the reference (strain-rate term c refused by name)",
    ),
    s("/PROP/TYPE6 (/PROP/SOL_ORTH)", &["/PROP/TYPE6/1", "/PROP/SOL_ORTH/1"], "orthotropic solid sections on one-point bricks (Isolid 1, 2) and HEPH (24): Ip 0 (global axes), 1, 2, 3 (angle phi in an element plane), directions following the element; skews, Iorth 1, other Ip and other formulations refused by name; laws other than LAW12 refused there"),
    s("/PROP/TYPE1 (/PROP/SHELL)", &["/PROP/TYPE1/1", "/PROP/SHELL/1"], "shell sections: Ishell, Ismstr, Ithick, Iplas, N, thickness, hourglass coefficients"),
    s("/PROP/TYPE14 (/PROP/SOLID)", &["/PROP/TYPE14/1", "/PROP/SOLID/1"], "solid sections: Isolid 1, 2 (one point; Ismstr 1, small strain from t = 0 on the initial shape turned with the element; Ismstr 10, total strain, with LAW62), 12 (S8), 14 (HA8), 17 (H8C; an input version before 2019 reads 12 as 17), Icpre and Inpts, hourglass coefficients, dtmin"),
    s("/PROP/TYPE4 (/PROP/SPRING)", &["/PROP/TYPE4/1", "/PROP/SPRING/1"], "axial springs: K, C, the force curve with hardening H = 0, 1, 2, 4, 5, 6, 7, 8 and its unloading curve, the rate terms A + B ln(δ̇/D) + E g(δ̇/F) and Hscale h(δ̇/F), failure bounds, Ileng (sensor refused)"),
    s("/PROP/TYPE8 (/PROP/SPR_GENE)", &["/PROP/TYPE8/1", "/PROP/SPR_GENE/1"], "general springs: six degrees of freedom in the global frame, each with the TYPE4 law; Ifail 0/1 (Fsmooth filter), Ifail2 0/1 (skew, Iequil 1, Ifail2 2, sensor refused)"),
    s("/PROP/TYPE13 (/PROP/SPR_BEAM)", &["/PROP/TYPE13/1", "/PROP/SPR_BEAM/1"], "spring beams: tension, shears, torsion and bendings in the element's frame, each with the TYPE4 law, shear balanced by end moments; Ifail 0/1, Ifail2 0/2, Ileng (skew, Ifail2 1/3, sensor refused)"),
    s("/PROP/TYPE45 (/PROP/KJOINT2)", &["/PROP/TYPE45/1", "/PROP/KJOINT2/1"], "joints between two rigid bodies' secondary nodes: types 1 (spherical), 8 (rigid) and 9 (free) in the global frame turned with the nodes; blocked degrees of freedom with Kn or the automatic stiffness (Kn = 0, from the bodies' masses and inertias at the /DTIX step) and critical damping Cr; free ones with K, C and their functions (types 2-7, skews, stops, friction and the sensor refused by name)"),
    s("/PROP/TYPE2 (/PROP/TRUSS)", &["/PROP/TYPE2/1", "/PROP/TRUSS/1"], "trusses: Area; axial bar with large displacements, LAW1, LAW2, LAW36, LAW44 uniaxial (no strain-rate term, as the reference); Gap > 0 refused"),
    s("/PROP/TYPE3 (/PROP/BEAM)", &["/PROP/TYPE3/1", "/PROP/BEAM/1"], "beams: Area, Iyy, Izz, Ixx, dm, df (0.01 blank), Ishear; Timoshenko resultants, corotational, global plasticity with LAW2, LAW36, LAW44 (the reference's work-equivalent strain rate); released rotations, small-strain Ismstr and stubby beams (A·L²/12I < 1) refused by name"),
    s("/DEF_SHELL, /DEF_SOLID", &["/DEF_SHELL", "/DEF_SOLID"], "defaults for shell and solid sections"),
    s("/FUNCT", &["/FUNCT/1"], "tabulated functions"),
    s("/SKEW/FIX, /SKEW/MOV, /SKEW/MOV2", &["/SKEW/FIX/1", "/SKEW/MOV/1", "/SKEW/MOV2/1"], "skew frames (fixed from Y′ and Z′; moving from three nodes with Dir X, Y, Z), checked on the initial geometry; conditions, springs and rigid bodies in a skew are refused by name, a time history in a skew is written in the global frame (said in a warning)"),
    s("/ADMAS", &["/ADMAS/0/1", "/ADMAS/1/1"], "added mass, types 0 (per node) and 1 (shared)"),
    s("/GRNOD/NODE, /GRNOD/GRNOD, /GRNOD/PART, /GRNOD/SURF, /GRNOD/GRSHEL, /GRNOD/BOX", &["/GRNOD/NODE/1", "/GRNOD/GRNOD/1", "/GRNOD/PART/1", "/GRNOD/SURF/1", "/GRNOD/GRSHEL/1", "/GRNOD/BOX/1"], "node groups (of nodes, groups, parts' elements, surfaces' segments, shell groups' shells, the nodes in a box)"),
    s("/GRSHEL/SHEL, /GRSHEL/BOX, /GRSHEL/BOX2", &["/GRSHEL/SHEL/1", "/GRSHEL/BOX/1", "/GRSHEL/BOX2/1"], "shell groups: listed 4-node shells, or those with all (BOX) or at least one (BOX2) node in a box on the initial geometry"),
    s("/BOX/RECTA, /BOX/SPHER, /BOX/CYLIN", &["/BOX/RECTA/1", "/BOX/SPHER/1", "/BOX/CYLIN/1"], "selection boxes for groups: points from nodes or coordinates, the surface inside; a rectangular box in a skew refused by name"),
    s(
        "/SURF/PART (/EXT, /ALL), /SURF/GRSHEL, /SURF/SEG",
        &["/SURF/PART/1", "/SURF/PART/EXT/1", "/SURF/GRSHEL/1", "/SURF/SEG/1"],
        "surfaces",
    ),
    s("/SURF/ELLIPS", &["/SURF/ELLIPS/1"], "hyper-ellipsoid surfaces (degree n, centre, semi-axes along the axes of skew_ID at t = 0, then turning with the /RBODY that carries them), the main side of /INTER/TYPE14 and /INTER/TYPE15"),
    s("/LINE/SEG, /LINE/PART, /LINE/SURF, /LINE/EDGE", &["/LINE/SEG/1", "/LINE/PART/1", "/LINE/SURF/1", "/LINE/EDGE/1"], "lines (2-node segments) for edge-to-edge contact: explicit, the trusses and beams of parts, every edge of surfaces, the free edges of surfaces"),
    s("/SUBSET", &["/SUBSET/1"], "subsets of parts"),
    s("/BCS", &["/BCS/1"], "boundary conditions (a skew system refused)"),
    s("/IMPVEL, /IMPDISP", &["/IMPVEL/1", "/IMPDISP/1"], "imposed velocities and displacements (skew, sensor, frame, cylindrical and rotations refused)"),
    s("/IMPDISP/FGEO", &["/IMPDISP/FGEO/1"], "nodes driven along straight lines to their final positions, the path's fraction a time function (Ascale, Tstart, Tstop); rotations free; spring targets (part_ID) and sensors refused by name"),
    s("/MOVE_FUNCT", &["/MOVE_FUNCT/1"], "scales and shifts a /FUNCT's points in place (Ascale_x, Fscale_y, Ashift_x, Fshift_y)"),
    s("/INIVEL/TRA, /INIVEL/ROT", &["/INIVEL/TRA/1", "/INIVEL/ROT/1"], "initial velocities"),
    s("/CLOAD, /GRAV", &["/CLOAD/1", "/GRAV/1"], "concentrated loads and gravity (skew and sensor refused)"),
    s("/PLOAD", &["/PLOAD/1"], "pressure on a surface's segments, p·N/8 per quadrangle node (p·N/6 per triangle node) at the current geometry, ended with the element under it unless Idel 2 (sensor, Ipinch, Itypfun 2/3 refused by name)"),
    s("/DAMP", &["/DAMP/1"], "Rayleigh damping of a node group: α, β for every degree of freedom or one pair each, Tstart, Tstop; its work in the external work, the time step reduced (skew refused; /DAMP/INTER, VREL, FREQ_RANGE not read)"),
    s("/RWALL/PLANE", &["/RWALL/PLANE/1"], "rigid walls: fixed, moving with their node, or free with their own mass; friction"),
    s("/RBODY", &["/RBODY/1"], "rigid bodies (the elements whose nodes all belong to one body are deactivated: no time step): MASS, added inertia, ICOG 0/1 (centre of mass) and 3 (the main node), ISPHER 1 (spherical inertia); the main node's /INIVEL is the body's; surf_ID: the /SURF/ELLIPS the body carries (sensor, skew, IKREM, ICOG 2/4 and other surfaces refused)"),
    s("/SECT", &["/SECT/1"], "read; its forces are not written yet (an output request: it changes nothing in the solution)"),
    s("/INTER/TYPE2", &["/INTER/TYPE2/1"], "tied interfaces, Spotflag 5 and Spotflag 4 (translations only) (other Spotflags, Level, Idel2, rupture refused by field)"),
    s("/INTER/TYPE3, /INTER/TYPE5", &["/INTER/TYPE3/1", "/INTER/TYPE5/1"], "surface-to-surface and node-to-surface contact; IRS/IRM orient the one-sided surfaces (0 turns solid faces that point into their solid, 1 reverses every segment, 2 keeps them as given) (TYPE5's sens_ID, Inacti and Ptlim refused by name)"),
    s("/INTER/TYPE7", &["/INTER/TYPE7/1"], "general contact: every card of the reference (Istf, Igap, Inacti, friction, VISs, Idel, IBC; Irem_gap 2 leaves out, per segment, the secondary nodes within √2·gap of it along the surface, as the reference starter)"),
    s("/INTER/TYPE6", &["/INTER/TYPE6/1"], "rigid body contact between two surfaces on two /RBODY: the total force a function of the largest penetration (fct_IDld, Ascalex, FscaleId, EQ. 8.7.6.1), shared by penetration, Gap, Visc, Coulomb friction (Fric), the time step of EQ. 8.7.5, Iform 1/2 (unloading and reloading along Stiff between the loading curve and the unloading curve fct_IDul, Fscaleul, or zero), friction curves of the node's normal force and sliding speed (fct_IDff, fct_IDfv, Ascalef, Ascalev), damping curves (fct_IDdv, Fscalev, fct_IDdf) IRS/IRm orientation as TYPE3's (Sfric, Icor, Inacti 5 refused by name)"),
    s("/INTER/TYPE14", &["/INTER/TYPE14/1"], "nodes against a rigid hyper-ellipsoid (/SURF/ELLIPS, moving with the /RBODY that names it): Stif, Gap, the total elastic force a curve of the largest penetration (fct_IDld) or linear node springs, the reaction and its moment on the body, Visc (each node's normal damper Visc·2·√(k·m), or Visc·g1(v_n)·g2(F_e) with fct_IDd1/fct_IDd2), Coulomb friction Fric (an elastic tangential spring of the node's stiffness, capped at μ·F_n, μ = Fric·gf(F_e) with fct_IDf)"),
    s("/INTER/TYPE15", &["/INTER/TYPE15/1"], "segments against a rigid hyper-ellipsoid (/SURF/ELLIPS, moving with the /RBODY that names it): each 4-node segment as its four triangles around the centre, each 3-node one as it is; Stif, the stiffness Stif·[D/(D − p)]² growing as a facet nears the centre (D the depth of the tangent plane), the reaction and its moment on the body, Coulomb friction Fric (an elastic tangential spring, capped at μ·F_n; the ball rolls), the kinematic time step of §8.10"),
    s("/INTER/TYPE11", &["/INTER/TYPE11/1"], "edge-to-edge contact between /LINE sides or in self-contact: Istf, Igap 0/1/3, Gapmin, Stfac, Coulomb friction (Iform 1, 2), VISs, Bumult, Idel, Inacti 1/2 (Inacti 3/5/6, IBC, dtmin, Irem_gap 2, sensor, heat and /FRICTION refused by name)"),
    s("/INTER/TYPE19", &["/INTER/TYPE19/1"], "general contact, computed as Radioss does: TYPE7 node-to-surface both ways (one in self-contact) and TYPE11 between the surfaces' edges (Iedge 2 all, 1 free); Igap 0-4, Edge_scale_gap; the added interfaces take ids after the deck's largest"),
    s("/INTER/TYPE24", &["/INTER/TYPE24/1"], "penalty node-to-surface contact (self, two surfaces both ways, or nodes to a surface), computed with TYPE25's kernel: a new impact takes the full stiffness, a node penetrated at the start feels nothing until it leaves (Inacti 5: the penetration at each impact as a baseline), no force jumps, Istf (2-5 with the secondary nodes' assembled stiffness, as TYPE25), Stfac, Stmin/Stmax, the mass and time-step stiffness (IPSTIF, Istf 7, Stfac_mdt, DTstif), the shells' half thicknesses as gap capped by Gap_max_s/Gap_max_m, VISs, Coulomb friction, Idel, Igap0 (Istf 1/6/12-14, Iedge, Inacti -1/1/3, Ipen0 1, Ipen_max, Ifric laws, sensor, /FRICTION refused by name)"),
    s("/INTER/TYPE25", &["/INTER/TYPE25/1"], "penalty node-to-surface contact without activation gap (self, two surfaces both ways, or nodes to a surface): the penetration at impact as a baseline, no force jumps, Istf (2-5 with the secondary nodes' assembled stiffness of the reference starter: B̄·(2·V_n)^(1/3) of their solids plus the mean E·t of their shells), Stfac, the mass and time-step stiffness (IPSTIF, Stfac_mdt, DTstif), Gap_scale, Gap_max, VISs with IVIS2 1/4/6, Coulomb friction, Idel, Igap0, faces between two solids (/SURF/PART/ALL) dormant until one of the two is deleted; Igap 2: each segment leaves out the secondary nodes within √2·gap of it along the surface (as TYPE7's Irem_gap 2); Igap 3: each side's gap at most %mesh_size times its shortest edge; Iedge 1: the free shell edges in edge-to-edge contact (an added interface, TYPE25's penalty on edge pairs: the impact's penetration a baseline that relaxes at 5 % a cycle toward a smaller one) (Iedge 11/13/22, Igap 5, Igap 3 with Iedge 1, Ishape 2, Ithick, Inacti -1/1/3, Ifric laws, sensor, heat, /FRICTION refused by name)"),
    s("/TH/*", &["/TH/NODE/1", "/TH/PART/1"], "time-history requests: the run file's /th tables (nodes, parts, interfaces, rigid walls, global energies)"),
    s("/ANIM/*", &["/ANIM/VECT/DISP"], "animation requests: states at /ANIM/DT in the run file"),
    s("/ANALY, /SPMD, /IOFLAG, /SHFRA/V4, /SHFRA/V5", &["/ANALY", "/SPMD", "/IOFLAG", "/SHFRA/V4"], "read; they change nothing in the solution (N2D3D other than 0 refused)"),
    s("/RANDOM, /RANDOM/GRNOD", &["/RANDOM", "/RANDOM/GRNOD/1"], "the reference starter's random noise (Xalea, Seed) added to the initial coordinates, every node in reading order or a group's; a unit system of its own refused"),
    s("//SUBMODEL, //ENDSUB", &["//SUBMODEL/1", "//ENDSUB"], "submodels read in place: ids and coordinates as written (id offsets, a unit system or version of their own, a /BEGIN inside refused by name)"),
    e("/RUN", &["/RUN/NAME/1"], "end time"),
    e("/DT", &["/DT"], "time step scale and minimum (the per-type controls /DT/<type>/<action>, other nodal options and /DT/AMS are not computed: refused by name); while a TYPE7, 11, 19, 24 or 25 interface is active every node's step √(2M/(K_el + K_c)) is a candidate too, K_el from its elements as the reference's element step routines give it (BT shells 0.81·½V0·E/L², QEPH and QBAT ½V0·A11/L², solids ¼·ρV/Δt²), K_c the contact's"),
    e("/DT/NODA", &["/DT/NODA/0"], "the time step from the nodes (scale) without added mass, as /DT/NODA/CST computes it; Tmin acts on nothing (no action keyword)"),
    e("/DT/BRICK/CST", &["/DT/BRICK/CST/0"], "read; in a model without solids it changes nothing (with bricks or tetrahedra refused by name)"),
    e("/DT/NODA/CST", &["/DT/NODA/CST/0"], "the time step from the nodes (scale, minimum): each node under the minimum gets the mass and inertia that bring it there (MASS ADDED, MAS.ERR); 4-node shells, trusses and beams give their nodal stiffness, rigid bodies step at their main node (Σ K, Σ K_rot + d²K, the smallest principal inertia), other elements refuse it by name"),
    e("/PRINT", &["/PRINT/-100/55"], "listing period"),
    e("/ANIM/DT, /ANIM/*", &["/ANIM/DT", "/ANIM/ELEM/VONM"], "state period of the run file"),
    e("/TFILE", &["/TFILE/4"], "time-history period (0: every cycle)"),
    e("/RFILE", &["/RFILE/1", "/RFILE/OFF"], "restart file period"),
    e("/STOP", &["/STOP"], "Emax energy-error stop, NTH/NANIM checks"),
    e("/DAMP", &["/DAMP/1"], "new α, β for a starter /DAMP from this run on"),
    e("/DTIX", &["/DTIX"], "the first time step at most DT_ini, every step at most DT_max (the step of a model without elements)"),
    e("/RBODY/ON", &["/RBODY/ON"], "the rigid bodies it names must exist; they are active from the start, so it switches nothing (/RBODY/OFF not read)"),
    e("/PARITH, /MON, /VERS, /PROC, /TITLE", &["/PARITH/ON", "/MON/ON", "/VERS/2019", "/PROC/1", "/TITLE"], "read; results are the same on any number of ranks and threads anyway"),
];

/// The table as Markdown, with the keywords skipped because they change
/// nothing in the solution (the keyword policy's list) at the end.
pub fn markdown() -> String {
    let mut out =
        String::from("| File | Keyword | What crashsim does with it |\n| --- | --- | --- |\n");
    for r in SUPPORTED {
        let file = match r.file {
            File::Starter => "starter",
            File::Engine => "engine",
        };
        out += &format!("| {file} | {} | {} |\n", r.keyword, r.what);
    }
    for (k, why) in SAFE_TO_SKIP {
        out += &format!("| any | /{k} | skipped with a warning: {why} |\n");
    }
    out += "\nEvery other keyword is unsupported: `check` lists it, `run` stops on it by name \
            (exit 2) unless `--skip-unsupported`.\n";
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deck::source::Block;
    use crate::model::Loc;

    fn block(header: &str) -> Block {
        Block {
            header: header.to_string(),
            parts: crate::deck::source::header_parts(header),
            loc: Loc {
                file: "table".into(),
                line: 1,
            },
            lines: Vec::new(),
        }
    }

    /// Every header of the table is read by a family parser: with no cards
    /// it may fail for a missing card, but never as a keyword (or variant)
    /// nobody reads.
    #[test]
    fn every_keyword_in_the_table_is_read() {
        for r in SUPPORTED {
            for h in r.headers {
                let b = block(h);
                let read = match r.file {
                    File::Starter => crate::deck::read_starter_block(&b, &mut Default::default()),
                    File::Engine => {
                        crate::deck::engine::parse_engine_block(&b, &mut Default::default())
                    }
                };
                match read {
                    Ok(true) => {}
                    Ok(false) => panic!("{h}: the table lists it, the reader does not read it"),
                    Err(e) => assert!(
                        !e.variant_not_read,
                        "{h}: a variant the reader does not read"
                    ),
                }
            }
        }
    }

    #[test]
    fn keywords_nobody_reads_are_not_in_the_table() {
        for h in ["/MAT/LAW25/1", "/INTER/TYPE19/1", "/RWALL/CYL/1"] {
            assert!(
                !matches!(
                    crate::deck::read_starter_block(&block(h), &mut Default::default()),
                    Ok(true)
                ),
                "{h} is read: add it to the table"
            );
        }
        let md = markdown();
        assert!(
            md.contains("| starter | /INTER/TYPE7 |") && md.contains("| any | /MEMORY |"),
            "{md}"
        );
    }
}
