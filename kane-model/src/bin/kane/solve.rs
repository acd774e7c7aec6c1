//! `kane solve`: the systems a file asks for with CODE ALGEBRAIC and CODE NONLINEAR, solved at
//! its INPUT values (and `--set`), printed as `X = value` lines or one JSON object.

use std::path::PathBuf;

use kane_model::expr::SymbolId;
use kane_model::lang::{self, algebraic::Solution};

use super::output::outln;
use super::{read, values_with_sets};

/// One request solved: its kind, line, unknowns and solution.
struct Solved {
    kind: String,
    line: usize,
    names: Vec<String>,
    solution: Solution,
}

/// Solves every CODE ALGEBRAIC / NONLINEAR request of `file`; an error names the request.
pub fn solve(file: PathBuf, set: Vec<String>, json: bool) -> Result<(), String> {
    let source = read(&file)?;
    let mut m = lang::load(&file.display().to_string(), &source).map_err(|r| r.render())?;
    let values = values_with_sets(&m, &set)?;
    let requests: Vec<_> = m.code.iter().filter(|c| c.system.is_some()).cloned().collect();
    if requests.is_empty() {
        return Err(format!(
            "{}: the file asks for no CODE ALGEBRAIC(EQN, X, ...) or CODE NONLINEAR(EQN, X, ...) to solve",
            file.display()
        ));
    }
    let upper: Vec<String> = m.model.ar.symbols().map(|(_, info)| info.name.to_ascii_uppercase()).collect();
    let value_of = |s: SymbolId| values.get(&upper[s.index()]).copied();
    let mut solved = Vec::with_capacity(requests.len());
    for request in requests {
        let system = request.system.as_ref().expect("filtered");
        let line = lang::line_column(&source, request.span.start).0;
        let solution = system
            .solve(&mut m.model.ar, &value_of)
            .map_err(|e| format!("{}:{line}: CODE {}: {e}", file.display(), request.kind))?;
        solved.push(Solved { kind: request.kind.clone(), line, names: system.names.clone(), solution });
    }
    if json {
        let each: Vec<serde_json::Value> = solved
            .iter()
            .map(|s| {
                serde_json::json!({
                    "kind": s.kind, "line": s.line, "unknowns": s.names, "values": s.solution.values,
                    "iterations": s.solution.iterations, "residual": s.solution.residual,
                })
            })
            .collect();
        outln!("{}", serde_json::json!({ "systems": each }));
        return Ok(());
    }
    for s in &solved {
        outln!(
            "% CODE {} (line {}): {} step(s), largest residual {:.1e}",
            s.kind,
            s.line,
            s.solution.iterations,
            s.solution.residual
        );
        for (name, v) in s.names.iter().zip(&s.solution.values) {
            outln!("{name} = {v}");
        }
    }
    Ok(())
}
