//! Where each line of a `--model` run's generated scene came from: an [`Origin`] per line, so an
//! error at a line of a scene the user never saw is told at what they gave instead (`--set
//! Q1=abc`, `--t-final`, or the model file's INPUT or OUTPUT line).

use std::path::Path;

/// The name a generated scene is parsed under.
pub const GENERATED: &str = "<command line>";

/// What a line of the generated scene came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// `--set NAME=VALUE`.
    Set {
        /// The name as given.
        name: String,
        /// The value as given.
        value: String,
    },
    /// A command-line option (`--t-final`, `--method`, `--rtol`, `--atol`).
    Option(&'static str),
    /// An INPUT of the model file (`TFINAL`, `INTEGSTP`, `RELERR`, `ABSERR`).
    Input(&'static str),
    /// The model file's OUTPUT command.
    Output,
    /// The model's value of a parameter or state (the file's INPUT line, or the model's default).
    Value(String),
    /// The model file as a whole (a default, the title, the model's name).
    File,
}

impl Origin {
    /// How a message names it, for the model file `file`.
    pub fn describe(&self, file: &Path) -> String {
        let file = file.display();
        match self {
            Origin::Set { name, value } => format!("--set {name}={value}"),
            Origin::Option(option) => option.to_string(),
            Origin::Input(name) => format!("{file}: INPUT {name}"),
            Origin::Output => format!("{file}: OUTPUT"),
            Origin::Value(name) => format!("{file}: the value of {name}"),
            Origin::File => file.to_string(),
        }
    }
}

/// A generated scene's text and each line's origin.
#[derive(Clone, Debug, Default)]
pub struct GeneratedScene {
    lines: Vec<(String, Origin)>,
}

impl GeneratedScene {
    /// Adds `line` (without its newline), from `origin`.
    pub fn push(&mut self, line: impl Into<String>, origin: Origin) {
        self.lines.push((line.into(), origin));
    }

    /// The scene's TOML text.
    pub fn text(&self) -> String {
        self.lines.iter().map(|(l, _)| format!("{l}\n")).collect()
    }

    /// The origin of 1-based line `line` (the file for a line past the end).
    pub fn origin(&self, line: usize) -> Origin {
        line.checked_sub(1).and_then(|i| self.lines.get(i)).map_or(Origin::File, |(_, o)| o.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_line_names_where_it_came_from() {
        let mut scene = GeneratedScene::default();
        scene.push("t_final = 5.0", Origin::Input("TFINAL"));
        scene.push("\"Q1\" = \"abc\"", Origin::Set { name: "Q1".into(), value: "abc".into() });
        assert_eq!(scene.text(), "t_final = 5.0\n\"Q1\" = \"abc\"\n");
        let file = Path::new("g.al");
        assert_eq!(scene.origin(1).describe(file), "g.al: INPUT TFINAL");
        assert_eq!(scene.origin(2).describe(file), "--set Q1=abc");
        assert_eq!(scene.origin(3).describe(file), "g.al");
        assert_eq!(scene.origin(0), Origin::File);
        assert_eq!(Origin::Option("--t-final").describe(file), "--t-final");
        assert_eq!(Origin::Output.describe(file), "g.al: OUTPUT");
    }
}
