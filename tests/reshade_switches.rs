//! Switch edits re-shaded from the hit cache keep the pixels whose colour cannot depend
//! on the switches that changed, and stay bit for bit a full re-trace.

mod reshade_harness;

use raylab::scene::Scene;
use raylab::trace::{RenderOptions, Term, TermSwitches};
use reshade_harness::{NOTHING, SCENES, Shot, edit_chain, example};

/// A switch edit shades only the pixels whose colour may depend on that switch, and
/// keeps the others: a chain of switches and solos, each from the one before, in every
/// scene, each pass bit for bit a full trace's (so no pixel that changes was kept).
#[test]
fn a_switch_shades_only_the_pixels_that_may_depend_on_it() {
    let all = 64 * 48;
    let set =
        |term: Term, on: bool| move |_: &mut Scene, o: &mut RenderOptions| o.switches.set(term, on);
    let solo = |term: Option<Term>| {
        move |_: &mut Scene, o: &mut RenderOptions| {
            o.switches = o.switches.with_solo(term);
        }
    };
    type Step = Box<dyn Fn(&mut Scene, &mut RenderOptions)>;
    let steps: Vec<(&str, Step)> = vec![
        ("specular off", Box::new(set(Term::Specular, false))),
        ("specular on", Box::new(set(Term::Specular, true))),
        ("diffuse off", Box::new(set(Term::Diffuse, false))),
        (
            "specular off too: no light looked at",
            Box::new(set(Term::Specular, false)),
        ),
        ("diffuse on", Box::new(set(Term::Diffuse, true))),
        ("specular on", Box::new(set(Term::Specular, true))),
        ("solo reflection", Box::new(solo(Some(Term::Reflection)))),
        ("no solo", Box::new(solo(None))),
        ("ambient off", Box::new(set(Term::Ambient, false))),
        ("shadows off", Box::new(set(Term::Shadows, false))),
        ("reflection off", Box::new(set(Term::Reflection, false))),
        ("solo specular", Box::new(solo(Some(Term::Specular)))),
        ("reflection on", Box::new(set(Term::Reflection, true))),
        ("solo ambient", Box::new(solo(Some(Term::Ambient)))),
        (
            "all on",
            Box::new(|_: &mut Scene, o: &mut RenderOptions| {
                o.switches = TermSwitches::ALL_ON;
            }),
        ),
    ];
    for name in SCENES {
        let base = Shot::of(example(name));
        let mut shots = Vec::new();
        let mut at = base.clone();
        for (_, step) in &steps {
            at = at.edited(|s, o| step(s, o));
            shots.push(at.clone());
        }
        let passes = edit_chain(&base, &shots, name);
        for (pass, (what, _)) in passes.iter().zip(&steps) {
            assert_eq!(pass.traced, NOTHING, "{name}, {what}");
            assert!(pass.shaded_pixels <= all, "{name}, {what}");
        }
        if name == "default.ron" {
            // Most of the default scene's pixels have no Phong lobe, and the sky's
            // pixels no ambient term.
            let shaded = |step: usize| passes[step].shaded_pixels;
            assert!(
                shaded(0) < all * 3 / 4 && shaded(0) > 0,
                "specular off: {}",
                shaded(0)
            );
            assert_eq!(shaded(1), shaded(0), "specular on again");
            assert!(
                shaded(8) < all && shaded(8) > 0,
                "ambient off: {}",
                shaded(8)
            );
        }
    }
}
