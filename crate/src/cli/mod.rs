//! The native `bodyspace` command-line program: one module per subcommand.

pub mod align;
pub mod info;
pub mod synth;
pub mod template;
