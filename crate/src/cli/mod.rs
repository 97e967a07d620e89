//! The native `bodyspace` command-line program: one module per subcommand.

pub mod info;
pub mod template;
