//! Results: in comes a trajectory; out go a CSV and a plot in display units, never
//! half-written, and put in place as one set (see `set`).

mod csv_file;
mod display;
mod events_csv;
mod plot;
mod set;
mod streamed;
mod temporaries;
mod view;
mod write;

pub use csv_file::write_csv;
pub use display::{column_name, display_table, Table};
pub use plot::{
    write_elevation, write_plot, write_sweep_metric, write_trace, write_work_precision, MemberPoint,
    MetricAxes, WorkPrecisionPoint,
};
pub use streamed::StreamedSet;
pub(crate) use temporaries::{remove_temporaries, unique_temporary, write_atomically, write_file_atomically};
pub use view::write_view;
pub(crate) use view::{page_html, script_json, view_data};
pub use write::{write, write_set, Written};

mod error;

pub use error::WriteError;
pub use plot::PlotError;
pub use set::SetError;
