//! End-to-end: a base model mapped to the fine resolution reconstructs exactly the subdivided
//! base body (no segment overridden), equals the base body on the base vertices (always), and
//! morphs incrementally at fine within 1e-6 m of a full reconstruction.

mod pca_support;

use bodyspace::model_file::file::read_model_for;
use bodyspace::pca::random::NormalRng;
use bodyspace::pca::subdivide::{subdivide_model, FineTemplate};
use bodyspace::pca::{
    build_body_model, BodyModel, BuildParams, Coefficients, Morph, TemplateIdentity,
};
use bodyspace::template::subdivide::Subdivision;
use bodyspace::template::{Resolution, Segment, Template};

fn subdivided(flat: &[f64], stencils: &[Vec<(u32, f64)>]) -> Vec<f64> {
    stencils
        .iter()
        .flat_map(|s| {
            let mut p = [0.0; 3];
            for &(u, w) in s {
                for a in 0..3 {
                    p[a] += w * flat[3 * u as usize + a];
                }
            }
            p
        })
        .collect()
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn random_coefficients(model: &BodyModel, seed: u64, overridden: &[Segment]) -> Coefficients {
    let mut c = Coefficients {
        whole: model.whole.random_coefficients(seed),
        ..Coefficients::default()
    };
    for (i, s) in overridden.iter().enumerate() {
        c.segments[s.index()] = Some(model.segment(*s).random_coefficients(seed + 1 + i as u64));
    }
    c
}

#[test]
fn the_tube_model_maps_to_one_level_of_subdivision_exactly() {
    let set = pca_support::training_set(12, 5);
    let params = BuildParams {
        variance: 1.0,
        compute_quality: false,
        ..BuildParams::default()
    };
    let base = build_body_model(&set, &params).unwrap();
    let v = base.template.vertex_count;
    let sub = Subdivision::new(v, &base.triangles, 1);
    // The fine blend weights as the template makes them: interpolated, then normalised.
    let weights: Vec<[f32; 6]> = sub
        .apply_values(&base.segment_weights)
        .into_iter()
        .map(|w| {
            let s: f32 = w.iter().sum();
            w.map(|x| x / s)
        })
        .collect();
    let fine_identity = TemplateIdentity {
        resolution: "fine".into(),
        vertex_count: sub.stencils.len(),
        ..base.template.clone()
    };
    let target = FineTemplate {
        base: base.template.clone(),
        fine: fine_identity.clone(),
        stencils: &sub.stencils,
        triangles: &sub.triangles,
        segment_weights: &weights,
    };
    let mut fractions = Vec::new();
    let fine = subdivide_model(&base, &target, &mut |f| fractions.push(f)).unwrap();
    assert_eq!(fine.template, fine_identity);
    assert_eq!(fine.whole.vertex_count(), sub.stencils.len());
    assert_eq!(fine.whole.variances, base.whole.variances);
    assert!(fractions.windows(2).all(|w| w[0] < w[1]));
    assert!((fractions.last().unwrap() - 1.0).abs() < 1e-12);

    // Whole body: S·(S̄ + ΦB) = S·S̄ + (S·Φ)·B.
    for seed in 0..4 {
        let c = random_coefficients(&base, seed, &[]);
        let expected = subdivided(&base.reconstruct(&c).unwrap(), &sub.stencils);
        let got = fine.reconstruct(&c).unwrap();
        let worst = max_abs_diff(&expected, &got);
        assert!(worst < 1e-6, "whole body differs by {worst} m");
    }
    // Segments overridden: identical on the base vertices, close elsewhere.
    let c = random_coefficients(&base, 9, &[Segment::Torso, Segment::LeftLeg, Segment::Head]);
    let base_body = base.reconstruct(&c).unwrap();
    let fine_body = fine.reconstruct(&c).unwrap();
    let on_base = max_abs_diff(&base_body, &fine_body[..3 * v]);
    assert!(on_base < 1e-6, "base vertices moved by {on_base} m");
    let elsewhere = max_abs_diff(&subdivided(&base_body, &sub.stencils), &fine_body);
    let seam = base.seam_report(&c).unwrap().max_jump;
    assert!(elsewhere <= seam, "{elsewhere} m vs seam jump {seam} m");

    // A model of another template is refused.
    let mut other = base.clone();
    other.template.hash = "ffffffff".into();
    assert!(subdivide_model(&other, &target, &mut |_| {}).is_err());
}

#[test]
fn the_demo_model_at_fine_is_the_subdivided_base_body_and_morphs_incrementally() {
    let template = Template::embedded().unwrap();
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/models/demo.bsm"
    ))
    .unwrap();
    let base = read_model_for(&bytes, &TemplateIdentity::of_template(&template)).unwrap();
    let fine_template = template.at_resolution(Resolution::Fine);
    let target = FineTemplate::of_templates(&template, &fine_template).unwrap();
    let t = std::time::Instant::now();
    let fine = subdivide_model(&base, &target, &mut |_| {}).unwrap();
    eprintln!(
        "demo model mapped to fine in {:.2} s",
        t.elapsed().as_secs_f64()
    );
    assert_eq!(fine.template.vertex_count, 214_050);
    assert_eq!(fine.template, TemplateIdentity::of_template(&fine_template));
    let stencils = fine_template.stencils().unwrap();
    let vb = base.template.vertex_count;

    let c = random_coefficients(&base, 3, &[]);
    let expected = subdivided(&base.reconstruct(&c).unwrap(), stencils);
    let mut out = vec![0.0f32; 3 * 214_050];
    fine.reconstruct_into(&c, &mut out).unwrap();
    let got: Vec<f64> = out.iter().map(|&x| x as f64).collect();
    let worst = max_abs_diff(&expected, &got);
    assert!(
        worst < 1e-6,
        "fine whole body differs from S·base by {worst} m"
    );

    // Six segments overridden: the base vertices of the fine body are the base body.
    let all = Segment::ALL;
    let mut c = random_coefficients(&base, 4, &all);
    let base_body = base.reconstruct(&c).unwrap();
    let mut morph = Morph::new(&fine, &c).unwrap();
    let on_base = max_abs_diff(
        &base_body,
        &morph.positions()[..3 * vb]
            .iter()
            .map(|&x| x as f64)
            .collect::<Vec<_>>(),
    );
    assert!(on_base < 1e-6, "base vertices moved by {on_base} m");

    // 600 slider moves at fine, whole body and segments in turn, then compare.
    let mut rng = NormalRng::new(11);
    for i in 0..600 {
        let part = i % 7;
        let (values, sds) = if part == 0 {
            (&mut c.whole, fine.whole.standard_deviations())
        } else {
            (
                c.segments[part - 1].as_mut().unwrap(),
                fine.segments[part - 1].standard_deviations(),
            )
        };
        let k = i % values.len();
        values[k] = rng.next_normal().clamp(-3.0, 3.0) * sds[k];
        let update = morph.update(&fine, &c).unwrap();
        assert!(!update.rebuilt && update.deltas == 1);
    }
    fine.reconstruct_into(&c, &mut out).unwrap();
    let worst = morph
        .positions()
        .iter()
        .zip(&out)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    eprintln!("fine, 600 moves: incremental vs full reconstruction {worst:.2e} m");
    assert!(worst < 1e-6, "{worst} m");
}
