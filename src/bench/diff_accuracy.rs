//! How often `raylab diff` is right, on scenes and bugs it was not tuned on. Each scene
//! (an example scene, or a random one of [`super::random_scene`]) gets bugs planted
//! ([`crate::compare::plant`]) alone, in pairs and in threes, at several severities and
//! on its lights and objects, and the diff of each picture is read: was each planted
//! bug named first, in the top two, or missed, and what was named instead. Pictures
//! with no bug (raylab's own render at other sample counts, and written in another
//! encoding) must get no verdict at all.
//!
//! The seeds are split: thresholds may be tuned on [`TUNING_SEEDS`]; the figures of
//! docs/BENCHMARKS.md are measured on [`MEASURED_SEEDS`] (and the example scenes).

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Serialize;

use crate::compare::plant::{Plant, PlantedBug, Site, plant};
use crate::compare::{
    ClampBug, CompareOptions, Encoding, Explanation, HIGH_CONFIDENCE, MIN_ERROR, NormalBug,
    OtherImage, Part, ShadowBug, SpawnBug, SpecularBug, SpotBug, compare_with_meshes,
};
use crate::scene::{ClampConvention, Light, MirrorConvention, Scene};
use crate::trace::{MeshStore, RenderProgress, Term};

/// Seeds whose random scenes the diff's thresholds may be tuned on.
pub const TUNING_SEEDS: Range<u64> = 0..1000;
/// Seeds whose random scenes the figures are measured on, never tuned on.
pub const MEASURED_SEEDS: Range<u64> = 1_000_000..1_001_000;

/// Causes that are places, not bugs: naming them claims no bug.
const PLACES: [&str; 3] = ["silhouette", "shading", "sampling"];

/// One scene's cases: which bugs, and what the diff said.
#[derive(Clone, Debug, Serialize)]
pub struct CaseResult {
    /// The scene.
    pub scene: String,
    /// The bugs planted, as `raylab render --bug` takes them (none: a correct picture).
    pub bugs: Vec<String>,
    /// For each bug, the rank (0 first) of the first explanation naming it.
    pub ranks: Vec<Option<usize>>,
    /// The causes the diff named, in order.
    pub named: Vec<String>,
    /// Per explanation, what it claimed and whether that was right.
    pub verdicts: Vec<Verdict>,
}

/// One explanation of a case, judged.
#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    /// Its confidence, 0 to 1 (printed as a sureness: high from 0.7).
    pub confidence: f64,
    /// Whether it claims a bug (not a place, an encoding or the sampling).
    pub claims: bool,
    /// Whether it names a planted bug.
    pub right: bool,
}

/// Whether naming `cause` claims a bug: places, encodings and sampling do not.
fn claims_a_bug(cause: &str) -> bool {
    !PLACES.contains(&cause)
        && !cause.starts_with("linear-")
        && cause != "truncate"
        && cause != "srgb"
}

/// Per cause: how often it was named when planted.
#[derive(Clone, Debug, Default, Serialize)]
pub struct CauseRow {
    /// Times planted (alone or with others).
    pub planted: u32,
    /// Named first (alone), or within the first as many as were planted (with others).
    pub first: u32,
    /// Named within the top two (alone), or within one more than were planted.
    pub top_two: u32,
    /// Not named at all.
    pub missed: u32,
    /// What was named first instead, where it was not named first: cause name -> times.
    pub mistaken_for: BTreeMap<String, u32>,
}

/// The figures of one run.
#[derive(Clone, Debug, Default, Serialize)]
pub struct AccuracyReport {
    /// Bugs planted alone: cases, named first, named in the top two.
    pub alone: (u32, u32, u32),
    /// Bugs of pairs (two per case): bugs, named in the top two, in the top three.
    pub pairs: (u32, u32, u32),
    /// Bugs of threes: bugs, named in the top three, in the top four.
    pub threes: (u32, u32, u32),
    /// Correct pictures, and those the diff claimed a bug in.
    pub no_bug: (u32, u32),
    /// Verdicts claiming a bug printed "high", and of those the ones naming a planted
    /// bug.
    pub high: (u32, u32),
    /// Per cause.
    pub causes: BTreeMap<String, CauseRow>,
    /// Every case.
    pub cases: Vec<CaseResult>,
}

impl AccuracyReport {
    /// Share of bugs planted alone named first.
    #[must_use]
    pub fn top1(&self) -> f64 {
        ratio(self.alone.1, self.alone.0)
    }
    /// Share of bugs planted alone named in the top two.
    #[must_use]
    pub fn top2(&self) -> f64 {
        ratio(self.alone.2, self.alone.0)
    }
    /// Share of the bugs of pairs named in the top two.
    #[must_use]
    pub fn pair_top2(&self) -> f64 {
        ratio(self.pairs.1, self.pairs.0)
    }
    /// Share of correct pictures the diff claimed a bug in.
    #[must_use]
    pub fn false_verdicts(&self) -> f64 {
        ratio(self.no_bug.1, self.no_bug.0)
    }
    /// Share of "high" verdicts that name a planted bug.
    #[must_use]
    pub fn high_right(&self) -> f64 {
        ratio(self.high.1, self.high.0)
    }

    fn add(&mut self, case: CaseResult) {
        let n = case.bugs.len();
        for verdict in case.verdicts.iter().filter(|v| v.claims) {
            if verdict.confidence >= HIGH_CONFIDENCE {
                self.high.0 += 1;
                self.high.1 += u32::from(verdict.right);
            }
        }
        if n == 0 {
            self.no_bug.0 += 1;
            let claimed = case.named.iter().any(|c| claims_a_bug(c));
            self.no_bug.1 += u32::from(claimed);
            self.cases.push(case);
            return;
        }
        let (first_within, top_within) = if n == 1 { (1, 2) } else { (n, n + 1) };
        let tally = match n {
            1 => &mut self.alone,
            2 => &mut self.pairs,
            _ => &mut self.threes,
        };
        for rank in &case.ranks {
            tally.0 += 1;
            tally.1 += u32::from(rank.is_some_and(|r| r < first_within));
            tally.2 += u32::from(rank.is_some_and(|r| r < top_within));
        }
        for (bug, rank) in case.bugs.iter().zip(&case.ranks) {
            let cause = bug.split('@').next().unwrap_or(bug);
            let cause = cause.split('=').next().unwrap_or(cause).to_owned();
            let row = self.causes.entry(cause).or_default();
            row.planted += 1;
            row.first += u32::from(rank.is_some_and(|r| r < first_within));
            row.top_two += u32::from(rank.is_some_and(|r| r < top_within));
            row.missed += u32::from(rank.is_none());
            if rank.is_none_or(|r| r >= first_within) {
                let instead = case
                    .named
                    .first()
                    .cloned()
                    .unwrap_or_else(|| "nothing".to_owned());
                *row.mistaken_for.entry(instead).or_default() += 1;
            }
        }
        self.cases.push(case);
    }
}

fn ratio(a: u32, b: u32) -> f64 {
    if b == 0 {
        1.0
    } else {
        f64::from(a) / f64::from(b)
    }
}

/// The bugs that can be planted in `scene`, one per cause and site choice, drawn with
/// `rng`: each light bug on a light of its kind, each object bug everywhere or on one
/// object, each term factor at one of three severities.
#[must_use]
pub fn candidate_bugs(scene: &Scene, rng: &mut fastrand::Rng) -> Vec<PlantedBug> {
    let lit: Vec<usize> = (0..scene.lights.len())
        .filter(|&l| !matches!(scene.lights[l], Light::Ambient { .. }))
        .collect();
    let spots: Vec<usize> = lit
        .iter()
        .copied()
        .filter(|&l| matches!(scene.lights[l], Light::Spot { .. }))
        .collect();
    let pick = |rng: &mut fastrand::Rng, list: &[usize]| list[rng.usize(0..list.len())];
    let object_site = |rng: &mut fastrand::Rng| {
        if scene.objects.len() > 1 && rng.bool() {
            Site::Node(vec![rng.usize(0..scene.objects.len())])
        } else {
            Site::Everywhere
        }
    };
    let severity = |rng: &mut fastrand::Rng| [0.0, 0.5, 2.0][rng.usize(0..3)];
    let mut bugs = Vec::new();
    let mut add = |plant, site| bugs.push(PlantedBug { plant, site });
    if !lit.is_empty() {
        add(Plant::LightOff, Site::Light(pick(rng, &lit)));
        add(
            Plant::Factor(Term::Diffuse, severity(rng)),
            Site::Light(pick(rng, &lit)),
        );
        add(Plant::Factor(Term::Specular, 0.0), Site::Everywhere);
        add(Plant::Factor(Term::Shadows, 0.0), Site::Everywhere);
    }
    add(
        Plant::Factor(Term::Ambient, severity(rng)),
        object_site(rng),
    );
    add(Plant::Factor(Term::Reflection, 0.0), Site::Everywhere);
    for b in NormalBug::ALL {
        add(Plant::Normal(b), object_site(rng));
    }
    for b in SpecularBug::ALL {
        add(Plant::Highlight(b), Site::Everywhere);
    }
    for b in ClampBug::ALL {
        add(Plant::Clamp(b), Site::Everywhere);
    }
    for b in ShadowBug::ALL {
        add(Plant::ShadowTest(b), object_site(rng));
    }
    for b in SpawnBug::ALL {
        add(Plant::Spawn(b), Site::Everywhere);
    }
    if !spots.is_empty() {
        for b in SpotBug::ALL {
            add(Plant::Spot(b), Site::Light(pick(rng, &spots)));
        }
    }
    let points: Vec<usize> = lit
        .iter()
        .copied()
        .filter(|&l| matches!(scene.lights[l], Light::Point { .. }))
        .collect();
    if !points.is_empty() {
        add(
            Plant::Spot(SpotBug::NoFalloff),
            Site::Light(pick(rng, &points)),
        );
    }
    add(Plant::OneSided, Site::Everywhere);
    add(Plant::MissingPart(Part::Caps), Site::Everywhere);
    if scene.objects.len() > 1 {
        add(
            Plant::MissingObject,
            Site::Node(vec![1 + rng.usize(0..scene.objects.len() - 1)]),
        );
    }
    add(Plant::ExtraObject, Site::Everywhere);
    add(Plant::Mirror(MirrorConvention::Blend), Site::Everywhere);
    add(Plant::ClampAt(ClampConvention::EachRay), Site::Everywhere);
    if !crate::compare::plant::has_glass(scene) {
        add(Plant::NoDepthLimit, Site::Everywhere);
    }
    add(Plant::Encoding(Encoding::LinearTruncate), Site::Everywhere);
    add(Plant::Encoding(Encoding::Srgb), Site::Everywhere);
    bugs
}

/// How many cases of each kind one scene gets.
#[derive(Clone, Copy, Debug)]
pub struct Plan {
    /// Bugs planted alone (drawn from the candidates; all of them where fewer).
    pub alone: usize,
    /// Pairs.
    pub pairs: usize,
    /// Threes.
    pub threes: usize,
}

/// Runs the cases of `scene` (named `name`) and adds them to `report`. A planted picture
/// that equals raylab's own (the bug has nothing to act on), or one of several bugs that
/// one of them hides, is not a case.
///
/// # Errors
/// The scene does not compile.
pub fn run_scene(
    name: &str,
    scene: &Scene,
    meshes: &MeshStore,
    plan: Plan,
    seed: u64,
    report: &mut AccuracyReport,
) -> Result<(), String> {
    let progress = RenderProgress::default();
    let mut rng = fastrand::Rng::with_seed(seed);
    let own = plant(scene, meshes, &[], 1, &progress).map_err(|e| e.to_string())?;
    let mut candidates = candidate_bugs(scene, &mut rng);
    rng.shuffle(&mut candidates);
    let mut cases: Vec<Vec<PlantedBug>> = candidates
        .iter()
        .take(plan.alone)
        .map(|b| vec![b.clone()])
        .collect();
    for (count, size) in [(plan.pairs, 2), (plan.threes, 3)] {
        for _ in 0..count {
            let mut chosen: Vec<PlantedBug> = Vec::new();
            for _ in 0..20 {
                let bug = candidates[rng.usize(0..candidates.len())].clone();
                // One bug per cause: two of the same read as one.
                if chosen
                    .iter()
                    .all(|c| c.plant.name() != bug.plant.name() && !exclusive(c.plant, bug.plant))
                {
                    chosen.push(bug);
                }
                if chosen.len() == size {
                    break;
                }
            }
            if chosen.len() == size {
                cases.push(chosen);
            }
        }
    }
    // Bugs that make the same picture as another candidate cannot be told apart by any
    // diff: naming either names both.
    let alone: Vec<Option<OtherImage>> = candidates
        .iter()
        .map(|b| plant(scene, meshes, std::slice::from_ref(b), 1, &progress).ok())
        .collect();
    let index_of = |bug: &PlantedBug| candidates.iter().position(|c| c == bug);
    let twins_of = |bug: &PlantedBug| -> Vec<PlantedBug> {
        let Some(i) = index_of(bug) else {
            return Vec::new();
        };
        (0..candidates.len())
            .filter(|&j| j != i && alone[j].is_some() && alone[j] == alone[i])
            .map(|j| candidates[j].clone())
            .collect()
    };
    for bugs in cases {
        // A bug alone was planted above already.
        let picture = match bugs.as_slice() {
            [bug] => index_of(bug).and_then(|i| alone[i].clone()),
            _ => plant(scene, meshes, &bugs, 1, &progress).ok(),
        };
        let Some(picture) = picture else {
            continue;
        };
        if !shows(&own, &picture) || !each_bug_shows(scene, meshes, &bugs, &picture) {
            continue;
        }
        let twins: Vec<Vec<PlantedBug>> = bugs.iter().map(&twins_of).collect();
        report.add(diff_case(name, scene, meshes, (&bugs, &twins), &picture)?);
    }
    // Correct pictures: raylab's own at other sample counts, and in the other encoding.
    for spp in [2, 4] {
        let mut more = scene.clone();
        more.render.samples_per_pixel = spp;
        let picture = plant(&more, meshes, &[], spp, &progress).map_err(|e| e.to_string())?;
        report.add(diff_case(name, scene, meshes, (&[], &[]), &picture)?);
    }
    report.add(diff_case(name, scene, meshes, (&[], &[]), &own)?);
    Ok(())
}

/// Whether `picture` differs from `own` by at least what the diff calls a difference
/// ([`MIN_ERROR`]: four channels a full 8-bit level outside their bytes). A byte a level
/// off may be rounding alone (a bug that moves a value across a rounding boundary moves
/// it a hair), so a channel counts by how far it is beyond one level. Less is rounding
/// noise no diff can name.
fn shows(own: &OtherImage, picture: &OtherImage) -> bool {
    let outside: f64 = own
        .rgb
        .iter()
        .zip(&picture.rgb)
        .flat_map(|(a, b)| (0..3).map(move |i| f64::from(a[i].abs_diff(b[i]))))
        .map(|levels| ((levels - 1.0).max(0.0) / 255.0).powi(2))
        .sum();
    outside >= MIN_ERROR
}

/// Whether each of `bugs` shows in `picture`: planted without it, the picture differs
/// ([`shows`]). A bug with nothing to act on, or hidden by another (a depth limit with
/// reflections off), leaves no trace to name.
fn each_bug_shows(
    scene: &Scene,
    meshes: &MeshStore,
    bugs: &[PlantedBug],
    picture: &OtherImage,
) -> bool {
    bugs.len() < 2
        || (0..bugs.len()).all(|i| {
            let mut others = bugs.to_vec();
            others.remove(i);
            plant(scene, meshes, &others, 1, &RenderProgress::default())
                .is_ok_and(|without| shows(&without, picture))
        })
}

/// Whether two bugs cannot be told apart when planted together (both encodings, both a
/// change of convention that the other undoes).
fn exclusive(a: Plant, b: Plant) -> bool {
    matches!((a, b), (Plant::Encoding(_), Plant::Encoding(_)))
}

/// The diff of `picture` against `scene` at 1 sample per pixel, read against `bugs`
/// (each named by its explanation, or by one of its twins': bugs whose picture alone is
/// the same).
fn diff_case(
    name: &str,
    scene: &Scene,
    meshes: &MeshStore,
    (bugs, twins): (&[PlantedBug], &[Vec<PlantedBug>]),
    picture: &OtherImage,
) -> Result<CaseResult, String> {
    let options = CompareOptions {
        samples_per_pixel: Some(1),
    };
    let comparison =
        compare_with_meshes(scene, meshes, picture, &options, &RenderProgress::default())
            .map_err(|e| format!("{name}: {e}"))?;
    let explanations: &[Explanation] = &comparison.explanations;
    let names = |i: usize, e: &Explanation| {
        bugs[i].is_named_by(e)
            || twins
                .get(i)
                .is_some_and(|t| t.iter().any(|b| b.is_named_by(e)))
    };
    let ranks = (0..bugs.len())
        .map(|i| explanations.iter().position(|e| names(i, e)))
        .collect();
    Ok(CaseResult {
        scene: name.to_owned(),
        bugs: bugs.iter().map(|b| b.label(scene)).collect(),
        ranks,
        named: explanations
            .iter()
            .map(|e| e.cause.name().to_owned())
            .collect(),
        verdicts: explanations
            .iter()
            .map(|e| Verdict {
                confidence: e.confidence,
                claims: claims_a_bug(e.cause.name()),
                right: (0..bugs.len()).any(|i| names(i, e)),
            })
            .collect(),
    })
}

/// Of the verdicts claiming a bug with at least each confidence (0.5 to 0.95 by 0.05):
/// how many, and the share naming a planted bug. What "high" should start at.
#[must_use]
pub fn calibration(report: &AccuracyReport) -> Vec<(f64, u32, f64)> {
    (10..20)
        .map(|step| {
            let at_least = f64::from(step) * 0.05;
            let chosen: Vec<&Verdict> = report
                .cases
                .iter()
                .flat_map(|c| &c.verdicts)
                .filter(|v| v.claims && v.confidence >= at_least)
                .collect();
            let right = chosen.iter().filter(|v| v.right).count();
            (
                at_least,
                chosen.len() as u32,
                ratio(right as u32, chosen.len() as u32),
            )
        })
        .collect()
}

/// The confusion table as text: one row per cause.
#[must_use]
pub fn confusion_table(report: &AccuracyReport) -> Vec<String> {
    let mut lines = vec![format!(
        "{:<28} {:>7} {:>6} {:>6} {:>6}  mistaken for",
        "cause", "planted", "first", "top 2", "missed"
    )];
    for (cause, row) in &report.causes {
        let mut instead: Vec<(&String, &u32)> = row.mistaken_for.iter().collect();
        instead.sort_by(|a, b| b.1.cmp(a.1));
        let instead: Vec<String> = instead
            .iter()
            .take(3)
            .map(|(c, n)| format!("{c} x{n}"))
            .collect();
        lines.push(format!(
            "{cause:<28} {:>7} {:>6} {:>6} {:>6}  {}",
            row.planted,
            row.first,
            row.top_two,
            row.missed,
            instead.join(", ")
        ));
    }
    lines
}

/// The accuracy run: `seeds` random scenes and the `examples` (resized to `width`
/// pixels wide), each with `plan`'s cases. Progress goes to stderr.
///
/// # Errors
/// A scene that does not compile.
pub fn accuracy_run(
    seeds: Range<u64>,
    examples: &[(String, Scene)],
    width: u32,
    plan: Plan,
) -> Result<AccuracyReport, String> {
    let mut report = AccuracyReport::default();
    let meshes = MeshStore::default();
    for (i, (name, scene)) in examples.iter().enumerate() {
        if !crate::scene::mesh_objects(scene).is_empty() {
            continue; // a mesh file is not at hand here
        }
        let mut scene = scene.clone();
        let height = (f64::from(scene.camera.height) * f64::from(width)
            / f64::from(scene.camera.width))
        .round() as u32;
        (scene.camera.width, scene.camera.height) = (width, height.max(1));
        scene.render.samples_per_pixel = 1;
        eprintln!("diff accuracy: {name}");
        run_scene(
            name,
            &scene,
            &meshes,
            plan,
            seeds.start + i as u64,
            &mut report,
        )?;
    }
    for seed in seeds {
        let height = width * 3 / 4;
        let scene = super::random_scene::random_scene(seed, width, height);
        eprintln!("diff accuracy: random scene {seed}");
        run_scene(
            &format!("random {seed}"),
            &scene,
            &meshes,
            plan,
            seed,
            &mut report,
        )?;
    }
    Ok(report)
}

/// The example scenes the benchmark report's accuracy keys are measured on (the
/// diff-accuracy run takes every example scene and more random ones).
const REPORT_SCENES: [&str; 3] = ["default.ron", "shapes.ron", "spotlights.ron"];

/// The accuracy run of `raylab bench`'s report: bugs planted in the example scenes
/// named in [`REPORT_SCENES`] (only `default.ron` in a `quick` run) and in random scenes
/// of the measured seeds (none in a quick run, two otherwise), at 200 pixels wide.
///
/// # Errors
/// A scene does not compile.
pub fn report_accuracy(
    examples: &[(String, Scene)],
    quick: bool,
) -> Result<AccuracyReport, String> {
    let wanted = if quick {
        &REPORT_SCENES[..1]
    } else {
        &REPORT_SCENES[..]
    };
    let chosen: Vec<(String, Scene)> = examples
        .iter()
        .filter(|(name, _)| wanted.contains(&name.as_str()))
        .cloned()
        .collect();
    let (seeds, plan) = if quick {
        (
            0,
            Plan {
                alone: 12,
                pairs: 3,
                threes: 0,
            },
        )
    } else {
        (
            2,
            Plan {
                alone: 24,
                pairs: 6,
                threes: 2,
            },
        )
    };
    let start = MEASURED_SEEDS.start;
    accuracy_run(start..start + seeds, &chosen, 200, plan)
}
