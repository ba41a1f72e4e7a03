"""The Python module's result of one case of scripts/product_outputs.sh, every
public value of the returned object (properties, and fields() of every step
of a run) as plain dicts of numpy arrays, numbers and strings, pickled for
scripts/compare_products.py.

    python_products.py COMMAND PRM DATA|- SETS OUT.pickle SOURCE_DIR

COMMAND is the command-line name (run, shoot, sweep, optimize, fit, response,
frequency-sweep); commands the module has no call for write nothing.
"""
import os
import pickle
import sys

import numpy as np

import cdea

SKIPPED = {"seconds", "results_path"}  # wall time; where a file would go


def plain(value):
    """value with its arrays, dicts, lists and numbers as plain Python data."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return value.copy()
    if isinstance(value, (str, bytes, int, float, complex, bool, type(None))):
        return value
    if isinstance(value, np.generic):
        return value.item()
    return describe(value)


def describe(result):
    """Every public property of a module object (no methods but fields())."""
    out = {"__type__": type(result).__name__, "__repr__": repr(result)}
    for name in dir(result):
        if name.startswith("_") or name in SKIPPED:
            continue
        value = getattr(result, name)
        if callable(value):
            continue
        out[name] = plain(value)
    if hasattr(result, "fields") and hasattr(result, "field_steps"):
        out["fields()"] = {int(k): plain(result.fields(int(k))) for k in result.field_steps}
    return out


def main():
    command, prm, data, sets, target, source = sys.argv[1:7]
    overrides = {}
    if sets:
        key, value = sets.removeprefix("--set ").split("=", 1)
        overrides[key] = value
    os.chdir(source)
    calls = {
        "run": lambda: cdea.run(prm, overrides),
        "shoot": lambda: cdea.shoot(prm, overrides),
        "sweep": lambda: cdea.sweep(prm, overrides),
        "optimize": lambda: cdea.optimize(prm, overrides),
        "response": lambda: cdea.response(prm, overrides),
        "frequency-sweep": lambda: cdea.frequency_sweep(prm, overrides),
    }
    if command == "fit":
        data_path = os.path.join(os.path.dirname(prm), data)
        header = [line for line in open(data_path) if not line.startswith("#")][0]
        viscous = "time_s" in header or "frequency_Hz" in header
        call = cdea.fit_viscoelastic if viscous else cdea.fit
        calls["fit"] = lambda: call(prm, data_path, overrides)
    if command not in calls:
        print(f"no Python call for '{command}'")
        return
    try:
        result = plain(calls[command]())
    except Exception as error:  # the error is a result too: compared as text
        result = {"__error__": f"{type(error).__name__}: {error}"}
    with open(target, "wb") as f:
        pickle.dump(result, f)
    print("written", target)


if __name__ == "__main__":
    main()
