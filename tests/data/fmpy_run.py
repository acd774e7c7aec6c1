"""Runs an FMU with FMPy as a client would: validates it, simulates it and writes the rows.

python3 fmpy_run.py FMU OUT.csv KIND STOP STEP RTOL NAME,NAME,... [NAME=VALUE ...]

KIND is ModelExchange (FMPy's own CVode solver) or CoSimulation (the FMU's integrator); RTOL is
the relative tolerance, or `default` for FMPy's. Exits non-zero, printing the problems, when the
FMU does not validate.
"""
import sys

import fmpy
import numpy as np
from fmpy.validation import validate_fmu


def main(argv):
    fmu, out, kind, stop, step, rtol, names = argv[1:8]
    starts = dict((kv.split("=")[0], float(kv.split("=")[1])) for kv in argv[8:])
    problems = validate_fmu(fmu)
    if problems:
        sys.exit("the FMU does not validate:\n" + "\n".join(problems))
    options = {}
    if rtol != "default":
        options["relative_tolerance"] = float(rtol)
    result = fmpy.simulate_fmu(fmu, fmi_type=kind, stop_time=float(stop), output_interval=float(step),
                               output=names.split(","), start_values=starts, **options)
    columns = ["time"] + names.split(",")
    np.savetxt(out, np.column_stack([result[c] for c in columns]), delimiter=",", header=",".join(columns),
               comments="", fmt="%.17g")


if __name__ == "__main__":
    main(sys.argv)
