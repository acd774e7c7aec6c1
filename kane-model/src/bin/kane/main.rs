//! The `kane` command: check model files, print, evaluate and compare their equations.

mod code;
mod fmu;
mod output;
mod solve;

use output::{out, outln};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use kane_model::codegen::CodeOptions;
use kane_model::expr::{ExprId, SymbolId};
use kane_model::lang::{self, LoadedModel};
use kane_model::mechanics::KaneEquations;

/// Kane's method for Autolev-style model files.
#[derive(Parser)]
#[command(name = "kane", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Parse, derive and check (assigned vs implied kinematics; implausible INPUT values as
    /// warnings); print the errors, or the warnings and a one-line summary.
    Check {
        /// The model file.
        file: PathBuf,
    },
    /// Print the kinematic equations, partial velocities, mass matrix and forcing; quantities
    /// too large to collect in named intermediates z1, z2, ... (Autolev's Z variables).
    Eoms {
        /// The model file.
        file: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: Format,
        /// Print the partial velocity table however long it is (by default a table longer
        /// than 64 KB is left out, with a note).
        #[arg(long)]
        partials: bool,
    },
    /// Evaluate the equations at one state (values from INPUT unless set; angles in radians).
    Eval {
        /// The model file.
        file: PathBuf,
        /// NAME=VALUE (case-insensitive), repeated.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// Solve the equations the file's CODE ALGEBRAIC and CODE NONLINEAR name, at its INPUT
    /// values (starting values of a nonlinear system's unknowns from INPUT too).
    Solve {
        /// The model file.
        file: PathBuf,
        /// NAME=VALUE (case-insensitive), repeated.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Print one JSON object: {"systems": [{"unknowns", "values", ...}]}.
        #[arg(long)]
        json: bool,
    },
    /// The state and input matrices A and B about the point the file's INPUT values define, by
    /// dual numbers through the generated right-hand side (constraints solved numerically).
    Linearize {
        /// The model file.
        file: PathBuf,
        /// NAME=VALUE (case-insensitive), repeated: the operating point.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// A constant taken as an input (a column of B), repeated; without any, B's columns
        /// are the model's inputs (SPECIFIED quantities the file gives no formula).
        #[arg(long = "input", value_name = "NAME")]
        input: Vec<String>,
        /// Print one JSON object: {"states", "inputs", "A", "B"}.
        #[arg(long)]
        json: bool,
    },
    /// Emit the model's Rust module (formatted), with --stats the operation counts.
    Gen {
        /// The model file.
        file: PathBuf,
        /// Where to write the module (standard output when absent).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Print the operation counts of rhs and outputs.
        #[arg(long)]
        stats: bool,
        /// Taylor coefficients too, for the Taylor method (a loop over the order).
        #[arg(long)]
        taylor: bool,
        /// Orders whose Taylor coefficients are also written out straight-line (e.g. 8,12,16;
        /// implies --taylor).
        #[arg(long, value_delimiter = ',')]
        taylor_orders: Vec<usize>,
        /// `rhs_lanes` too, for batches of members integrated in lock step.
        #[arg(long)]
        lanes: bool,
        /// The default drawing's outputs too: each frame's direction cosines `N_F` and each
        /// point's position `P_O_P` from the root point.
        #[arg(long)]
        drawing: bool,
    },
    /// Write the standalone programs the file's CODE statements ask for (CODE DYNAMICS()
    /// NAME.m, .c, .f90 or .py: the rhs, its outputs and a driver that writes the OUTPUT quantities as
    /// CSV), or with --lang one program in that language.
    Code {
        /// The model file.
        file: PathBuf,
        /// The folder the programs go to (default: the model file's).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// One program in this language (c, fortran, matlab, python) instead of the CODE statements.
        #[arg(long = "lang", value_name = "LANGUAGE")]
        language: Option<String>,
        /// Where the --lang program goes (default: the model's name and the language's
        /// extension, in the folder).
        #[arg(short = 'o', value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// Build the file's FMI 2.0 FMU for Model Exchange and Co-Simulation: model description,
    /// C source and a library for this platform (the system's C compiler: CC, else cc).
    Fmu {
        /// The model file.
        file: PathBuf,
        /// The FMU to write (default: the model's name and .fmu, beside the file).
        #[arg(short = 'o', value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// Check hand-derived equations (`U1' = ...` or `ZERO[1] = ...`) and quantities (V_P_A> = ...)
    /// against the derived ones, and say how they differ.
    Compare {
        /// The model file.
        file: PathBuf,
        /// The hand-derived equations.
        hand: PathBuf,
        /// Count an equation (`ZERO[r] = ...`) equal to a derived one negated as equal (a rate or
        /// a quantity of the opposite sign still differs).
        #[arg(long)]
        up_to_sign: bool,
    },
    /// Print any quantity of the model (scalar, vector, dyadic), simplified: I1, A_P_A>, ...
    Show {
        /// The model file.
        file: PathBuf,
        /// The quantity, as the model file would write it.
        name: String,
        /// Write vectors in this frame's unit vectors.
        #[arg(long)]
        frame: Option<String>,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Text,
    Latex,
    Json,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprint!("{message}");
            if !message.ends_with('\n') {
                eprintln!();
            }
            ExitCode::FAILURE
        }
    }
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))
}

fn load(path: &Path) -> Result<LoadedModel, String> {
    let src = read(path)?;
    lang::load(&path.display().to_string(), &src).map_err(|r| r.render())
}

fn equations<'a>(m: &'a LoadedModel, path: &Path) -> Result<&'a KaneEquations, String> {
    m.equations
        .as_ref()
        .ok_or_else(|| format!("{}: the file derives no equations; call KANE()", path.display()))
}

fn names(m: &LoadedModel, syms: &[SymbolId]) -> Vec<String> {
    syms.iter().map(|s| m.model.ar.symbol_info(*s).name.clone()).collect()
}

fn run(command: Command) -> Result<(), String> {
    match command {
        Command::Check { file } => check(file),
        Command::Eoms { file, format, partials } => eoms(file, format, partials),
        Command::Eval { file, set, json } => eval(file, set, json),
        Command::Solve { file, set, json } => solve::solve(file, set, json),
        Command::Linearize { file, set, input, json } => linearize(file, set, input, json),
        Command::Gen { file, out, stats, taylor, taylor_orders, lanes, drawing } => gen(
            file,
            out,
            stats,
            CodeOptions { taylor, taylor_orders, lanes, equation_counts: stats, drawing },
        ),
        Command::Code { file, out, language, output } => {
            code::code(code::CodeArgs { file, out_dir: out, language, output })
        }
        Command::Fmu { file, output } => fmu::fmu(file, output),
        Command::Compare { file, hand, up_to_sign } => compare(file, hand, up_to_sign),
        Command::Show { file, name, frame } => show(file, name, frame),
    }
}

/// `kane check`: the model loads and passes the checks (warnings printed); sizes of its equations.
fn check(file: PathBuf) -> Result<(), String> {
    let src = read(&file)?;
    // A large tree's M and f are left unformed, as `gen` leaves them: its order-n form needs
    // neither, and forming them only to print their size costs O(n^3).
    let checked = lang::check_for_generation(&file.display().to_string(), &src).map_err(|r| r.render())?;
    eprint!("{}", checked.warnings.render());
    let m = checked.model;
    let bookkeeping = lang::bookkeeping_summary(&m, &src);
    match &m.equations {
        Some(e) => {
            let dependent = match &e.constraints {
                Some(c) => {
                    format!(" and {} dependent ({})", c.dependent.len(), names(&m, &c.dependent).join(", "))
                }
                None => String::new(),
            };
            outln!(
                "{}: ok: {} ({}), {} ({}){dependent}, {}; {}",
                file.display(),
                counted(e.coordinates.len(), "coordinate", "coordinates"),
                names(&m, &e.coordinates).join(", "),
                counted(e.speeds.len(), "speed", "speeds"),
                names(&m, &e.speeds).join(", "),
                counted(m.model.bodies().len(), "body", "bodies"),
                equation_sizes(e, &m.model.ar),
            );
        }
        None => outln!("{}: ok: no KANE() in this file", file.display()),
    }
    if let Some(b) = bookkeeping {
        outln!("{}: bookkeeping {b}", file.display());
    }
    Ok(())
}

/// The sizes of Kane's `M` and `f` as `kane check` prints them: their operations when formed,
/// else their order and why they were not formed.
fn equation_sizes(e: &kane_model::mechanics::KaneEquations, ar: &kane_model::expr::Arena) -> String {
    if e.formed {
        return e.op_counts(ar).to_string();
    }
    let n = e.speeds.len();
    format!("M {n}x{n} not formed (a tree this large is generated in its order-n form, which needs neither M nor f; `kane eoms` forms them)")
}

/// `kane eoms`: the equations of motion, simplified and collected (or in named intermediates),
/// as text, LaTeX or JSON.
fn eoms(file: PathBuf, format: Format, partials: bool) -> Result<(), String> {
    let mut m = load(&file)?;
    let p = lang::printed_eoms(&mut m).map_err(|e| format!("{}: {e}", file.display()))?;
    let p = p.ok_or_else(|| format!("{}: the file derives no equations; call KANE()", file.display()))?;
    match format {
        Format::Latex => out!("{}", p.to_latex(&mut m.model.ar)),
        Format::Text => {
            out!("{}", p.to_text(&m.model.ar));
            let table = partial_velocities(&mut m)?;
            if partials || table.len() <= PARTIALS_TABLE_BUDGET {
                outln!("\n% Partial velocities and partial angular velocities");
                out!("{table}");
            } else {
                outln!(
                    "\n% Partial velocities and partial angular velocities: {} rows ({} KB) left out; \
                     --partials prints them",
                    table.lines().count(),
                    table.len() / 1000
                );
            }
        }
        Format::Json => {
            let mut table = partial_velocities(&mut m)?;
            let left_out = !partials && table.len() > PARTIALS_TABLE_BUDGET;
            if left_out {
                table.clear();
            }
            let t = p.texts(&m.model.ar);
            let v = serde_json::json!({
                "coordinates": p.coordinates, "speeds": p.speeds, "intermediates": t.intermediates,
                "kinematics": t.kinematics, "partial_velocities": table.lines().collect::<Vec<_>>(),
                "partial_velocities_left_out": left_out,
                "mass_matrix": t.mass_matrix, "forcing": t.forcing, "equations": t.equations,
                "dependent_speeds": p.dependent, "constraints": t.constraints,
            });
            outln!("{}", serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?);
        }
    }
    Ok(())
}

/// Longest partial velocity table `kane eoms` prints without `--partials`, in bytes.
const PARTIALS_TABLE_BUDGET: usize = 64_000;

/// The partial velocity table of the bodies' frames and mass centres.
fn partial_velocities(m: &mut LoadedModel) -> Result<String, String> {
    let frames: Vec<_> = m.model.bodies().iter().map(|b| b.frame).collect();
    let points: Vec<_> = m.model.bodies().iter().map(|b| b.mass_center).collect();
    m.model.partial_velocity_table(&frames, &points).map(|t| t.to_string()).map_err(|e| e.to_string())
}

/// The INPUT values of `m` by upper-case name, with `--set NAME=VALUE` overrides.
fn values_with_sets(m: &LoadedModel, set: &[String]) -> Result<BTreeMap<String, f64>, String> {
    let mut values: BTreeMap<String, f64> =
        m.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
    for s in set {
        let (k, v) = s.split_once('=').ok_or_else(|| format!("--set {s}: expected NAME=VALUE"))?;
        let v: f64 = v.trim().parse().map_err(|_| format!("--set {s}: `{}` is not a number", v.trim()))?;
        let key = k.trim().to_ascii_uppercase();
        if m.model.ar.symbols().all(|(_, info)| info.name.to_ascii_uppercase() != key) {
            return Err(format!("--set {s}: the model has no symbol `{}`", k.trim()));
        }
        values.insert(key, v);
    }
    Ok(values)
}

/// `kane linearize`: `A` and `B` about the point the file's INPUT values (and `--set`) define,
/// by dual numbers through the lowered right-hand side; `inputs` are parameters taken as inputs.
fn linearize(file: PathBuf, set: Vec<String>, inputs: Vec<String>, json: bool) -> Result<(), String> {
    let src = read(&file)?;
    let loaded = lang::check_for_generation(&file.display().to_string(), &src).map_err(|r| r.render())?.model;
    let values = values_with_sets(&loaded, &set)?;
    let name = file.file_stem().and_then(|s| s.to_str()).unwrap_or("model").to_string();
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", file.display());
    let mut spec = loaded.into_spec(&name).map_err(|e| fail(&e))?;
    let model = kane_model::program::ProgramModel::new(&mut spec).map_err(|e| fail(&e))?;
    let info = model.info();
    let upper = |s: &&str| s.to_ascii_uppercase();
    // The model's open inputs (SPECIFIED quantities without a formula) are zero unless set.
    let mut values = values;
    for &i in info.open_inputs {
        values.entry(upper(&info.param_names[i])).or_insert(0.0);
    }
    let missing: Vec<String> = info
        .param_names
        .iter()
        .chain(info.state_names)
        .map(upper)
        .filter(|n| !values.contains_key(n))
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "{}: no value for {}; give them with --set NAME=VALUE or INPUT",
            file.display(),
            missing.join(", ")
        ));
    }
    let params: Vec<f64> = info.param_names.iter().map(|s| values[&upper(s)]).collect();
    let mut y: Vec<f64> = info.state_names.iter().map(|s| values[&upper(s)]).collect();
    // B's columns: the constants named by --input, or else the model's inputs.
    let mut positions = Vec::with_capacity(inputs.len());
    for i in &inputs {
        let at = info.param(i);
        positions.push(at.ok_or_else(|| format!("--input {i}: not a constant or input the equations read"))?);
    }
    let inputs: Vec<String> = if inputs.is_empty() {
        positions = info.inputs.to_vec();
        positions.iter().map(|i| info.param_names[*i].to_string()).collect()
    } else {
        inputs
    };
    let assembly =
        model.assemble(&params, &mut y).transpose().map_err(|e| format!("{}: {e}", file.display()))?;
    let l = kane_model::program::linearize::linearize(model.program(), &params, 0.0, &y, &positions);
    if l.a.iter().chain(&l.b).flatten().any(|x| !x.is_finite()) {
        return Err(format!("{}: the linearisation is not finite at this point (a singular mass matrix or constraints losing rank)", file.display()));
    }
    let states = info.state_names;
    let moved: Vec<_> = assembly.iter().flat_map(|a| &a.moved).filter(|(_, from, to)| from != to).collect();
    if json {
        let assembled: serde_json::Map<String, serde_json::Value> =
            moved.iter().map(|(n, _, to)| (n.to_string(), serde_json::json!(to))).collect();
        let point: serde_json::Map<String, serde_json::Value> =
            states.iter().zip(&y).map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect();
        let value = serde_json::json!({
            "states": states, "inputs": inputs, "t": 0.0, "point": point, "assembled": assembled, "A": l.a, "B": l.b
        });
        outln!("{value}");
    } else {
        for (n, from, to) in moved {
            outln!("assembled: {n} = {to} (from {from}) so the configuration constraints hold");
        }
        let point: Vec<String> = states.iter().zip(&y).map(|(n, v)| format!("{n} = {v}")).collect();
        outln!("at t = 0: {} (states in the model's units, radians for angles)", point.join(", "));
        let inputs = if inputs.is_empty() { "none".to_string() } else { inputs.join(", ") };
        outln!("states: {}\ninputs: {inputs}", states.join(", "));
        for (n, row) in states.iter().zip(l.a.iter().zip(&l.b)) {
            let cells: Vec<String> = row.0.iter().chain(row.1).map(|x| format!("{x:.12e}")).collect();
            outln!("{n}' : {}", cells.join(" "));
        }
    }
    Ok(())
}

/// `kane eval`: the equations evaluated at a state.
fn eval(file: PathBuf, set: Vec<String>, json: bool) -> Result<(), String> {
    let m = load(&file)?;
    let e = equations(&m, &file)?;
    let values = values_with_sets(&m, &set)?;
    let ar = &m.model.ar;
    let mut roots: Vec<ExprId> = e.mass_matrix.iter().flatten().copied().collect();
    roots.extend(&e.forcing);
    roots.extend(&e.kinematics);
    let dependent: Vec<SymbolId> = e.constraints.as_ref().map(|c| c.dependent.clone()).unwrap_or_default();
    if let Some(c) = &e.constraints {
        roots.extend(c.a_dependent.iter().chain(&c.a_independent).flatten());
        roots.extend(c.b.iter().chain(&c.bias));
    }
    let loads: Vec<SymbolId> = e.loads.as_ref().map(|l| l.loads.clone()).unwrap_or_default();
    if let Some(l) = &e.loads {
        roots.extend(l.mass_rows.iter().chain(&l.load_columns).flatten().chain(&l.forcing));
    }
    let mut values = values;
    let unset = |s: &SymbolId, values: &BTreeMap<String, f64>| {
        !dependent.contains(s)
            && !loads.contains(s)
            && !values.contains_key(&ar.symbol_info(*s).name.to_ascii_uppercase())
    };
    let free = ar.free_symbols(&roots);
    // SPECIFIED quantities without a formula are inputs: zero unless set, said below.
    let open: Vec<String> = free
        .iter()
        .filter(|s| {
            unset(s, &values)
                && matches!(ar.symbol_info(**s).kind, kane_model::expr::SymbolKind::Specified { .. })
        })
        .map(|s| ar.symbol_info(*s).name.clone())
        .collect();
    for n in &open {
        values.insert(n.to_ascii_uppercase(), 0.0);
    }
    let missing: Vec<String> =
        free.iter().filter(|s| unset(s, &values)).map(|s| ar.symbol_info(*s).name.clone()).collect();
    if !missing.is_empty() {
        return Err(format!(
            "{}: no value for {}; give them with --set NAME=VALUE or INPUT",
            file.display(),
            missing.join(", ")
        ));
    }
    let value_of = |s: SymbolId| values.get(&ar.symbol_info(s).name.to_ascii_uppercase()).copied();
    let rates = e.rates_at(ar, &value_of).map_err(|err| format!("{}: {err}", file.display()))?;
    if !open.is_empty() {
        eprintln!("warning: {} left open by the file (SPECIFIED without a formula, or a variable without an equation): 0 here; give a value with --set {}=VALUE", open.join(", "), open[0]);
    }
    if json {
        let v = serde_json::json!({
            "coordinates": names(&m, &e.coordinates), "speeds": names(&m, &e.speeds),
            "dependent_speeds": names(&m, &dependent), "dependent_values": rates.dependent,
            "mass_matrix": rates.mass_matrix, "forcing": rates.forcing,
            "qdot": rates.coordinates, "udot": rates.speeds,
            "loads": names(&m, &loads), "load_values": rates.loads,
        });
        outln!("{v}");
    } else {
        for (name, v) in names(&m, &dependent)
            .iter()
            .zip(&rates.dependent)
            .chain(names(&m, &loads).iter().zip(&rates.loads))
        {
            outln!("{name} = {v}");
        }
        for (name, v) in names(&m, &e.coordinates).iter().zip(&rates.coordinates) {
            outln!("{name}' = {v}");
        }
        for (name, v) in names(&m, &e.speeds).iter().zip(&rates.speeds) {
            outln!("{name}' = {v}");
        }
    }
    Ok(())
}

/// `kane gen`: the generated Rust module, its report and generation time in its header,
/// written atomically.
fn gen(file: PathBuf, out: Option<PathBuf>, stats: bool, options: CodeOptions) -> Result<(), String> {
    let started = std::time::Instant::now();
    let emitted =
        kane_model::generate::generate_file(&file, &read(&file)?, &options).map_err(|e| match e {
            kane_model::generate::BuildError::Model(report) => report.render(),
            other => other.to_string(),
        })?;
    let source = kane_model::codegen::to_source(&emitted).map_err(|e| e.to_string())?;
    let (header, body) = source.split_once("\n\n").unwrap_or((&source, ""));
    let seconds = started.elapsed().as_secs_f64();
    let source = format!("{header}\n//! Generated in {seconds:.3} s.\n\n{body}");
    match out {
        Some(path) => write_output(&path, &source)?,
        None => out!("{source}"),
    }
    if stats {
        if let Some(ops) = emitted.equation_ops {
            eprintln!("equations (as `kane check` counts them): {ops}");
        }
        eprintln!(
            "lowered program: rhs {} operations per call; outputs {} operations for all of them",
            emitted.op_counts.rhs, emitted.op_counts.outputs
        );
    }
    Ok(())
}

/// Writes `text` to `path`: a regular file (or a new one) through a temporary file of this
/// process and a rename, never half-written; anything else (a symlink, a device such as
/// `/dev/null`, a pipe) is written through in place, never replaced.
fn write_output(path: &Path, text: &str) -> Result<(), String> {
    let fail = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    let regular = match std::fs::symlink_metadata(path) {
        Ok(meta) => meta.file_type().is_file(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => true,
        Err(e) => return Err(fail(path, e)),
    };
    if !regular {
        return std::fs::write(path, text).map_err(|e| fail(path, e));
    }
    let name = path.file_name().map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let tmp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let result = std::fs::write(&tmp, text)
        .map_err(|e| fail(&tmp, e))
        .and_then(|_| std::fs::rename(&tmp, path).map_err(|e| fail(path, e)));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// `kane compare`: hand-derived equations against the derived ones, and how they differ.
fn compare(file: PathBuf, hand: PathBuf, up_to_sign: bool) -> Result<(), String> {
    let (src, hand_src) = (read(&file)?, read(&hand)?);
    let mut outcome =
        lang::compare(&file.display().to_string(), &src, &hand.display().to_string(), &hand_src)
            .map_err(|r| r.render())?;
    outcome.up_to_sign = up_to_sign;
    out!("{outcome}");
    if outcome.differs() {
        Err("some equations differ".into())
    } else {
        Ok(())
    }
}

/// `kane show`: one quantity of the model, simplified.
fn show(file: PathBuf, name: String, frame: Option<String>) -> Result<(), String> {
    let src = read(&file)?;
    let text =
        lang::show(&file.display().to_string(), &src, &name, frame.as_deref()).map_err(|r| r.render())?;
    outln!("{text}");
    Ok(())
}

/// `n` with the singular or plural noun (`1 body`, `2 bodies`).
fn counted(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}
