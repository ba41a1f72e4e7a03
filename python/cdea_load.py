"""The pure-Python part of the module `cdea` (doc/python.md): `cdea.load`
of any results file, and `to_pandas()` / `to_xarray()` on the results of the
calls and of load. The compiled module imports this file at its end and
calls extend(); numpy, pandas, xarray and h5py are imported when first
needed, so that `import cdea` costs what it did before.

Files record no dimension names, only sizes and a description; the names
here (step, ring, frequency, ...) are given per product in DIMENSIONS, each
with the dataset that is its coordinate where there is one.
"""

import os

import cdea_products

# Per product and group: (dimension name, coordinate dataset or None); an
# array's axis takes the first name whose length it has (ring: the number of
# rings; `edge`: the two ring edges of a map).
DIMENSIONS = {
    "map": {"": [("rv", "rv_over_a"), ("outer_voltage", "outer_voltage_kV"), ("edge", None)]},
    "response": {"transfer": [("frequency", "frequency_Hz"), ("ring", None)],
                 "modes": [("mode", "frequency_Hz"), ("sample", "R_mm")]},
    "frequency sweep": {"sweep": [("frequency", "frequency_Hz")]},
    "fit": {"data": [("row", None), ("ring", None)], "curve": [("point", None), ("ring", None)],
            "samples": [("sample", None)], "tests": [("test", "file")],
            "": [("parameter", None)]},
    "chart": {"uniaxial": [("point", "stretch")], "equibiaxial": [("point", "stretch")],
              "dma": [("frequency", "frequency_Hz")]},
    "model selection": {"models": [("model", "model"), ("test", None)],
                        "constants": [("row", None)], "tests": [("test", "file")]},
    "optimum": {"history": [("evaluation", None), ("free_variable", None)],
                "optimum": [("point", "r_over_a")], "starts": [("start", None), ("edge", None)]},
}
# Arrays whose axes the lengths do not tell apart: their dimensions by name.
ARRAY_DIMENSIONS = {"s2_inner_edge_kPa": ("rv", "outer_voltage", "edge"),
                    "base_s2_inner_edge_kPa": ("rv", "edge"),
                    "red_line_s2_inner_edge_kPa": ("rv", "edge"),
                    "blue_line_s2_inner_edge_kPa": ("rv", "edge"),
                    # a model selection's per model and test file
                    "rms_kPa": ("model", "test"), "relative_rms": ("model", "test"),
                    "held_out_rms_kPa": ("model", "test"),
                    "held_out_relative_rms": ("model", "test")}
# The group of each product that to_pandas() gives by default.
MAIN_GROUP = {"map": "", "response": "transfer", "frequency sweep": "sweep", "fit": "data",
              "chart": "uniaxial", "optimum": "history", "model selection": "models"}


def dimension_names(shape, spec, sizes):
    """Names of the axes of an array of @p shape: the first of @p spec whose
    length (@p sizes) matches, each name once (a repeated one gets _2)."""
    names = []
    for length in shape:
        name = next((n for n, _ in spec if sizes.get(n) == length and n not in names), None)
        if name is None:
            name = next((n for n, _ in spec if sizes.get(n) == length), "dim")
            name = f"{name}_{len(names) + 1}"
        names.append(name)
    return names


def xarray_dataset(arrays, columns, spec, attrs):
    """An xarray.Dataset of the numeric @p arrays, each with its unit and
    description (@p columns), dimensions named by @p spec."""
    import numpy as np
    import xarray
    sizes = {}
    for name, coordinate in spec:
        if coordinate in arrays:
            sizes[name] = len(arrays[coordinate])
    for name, _ in spec:
        if name not in sizes:  # no coordinate: the most common length not yet named
            lengths = [a.shape[i] for a in arrays.values() for i in range(np.ndim(a))
                       if a.shape[i] not in sizes.values()]
            if lengths:
                sizes[name] = max(set(lengths), key=lengths.count)
    variables = {}
    for key, value in arrays.items():
        value = np.asarray(value)
        unit, description = columns.get(key, ("", ""))
        dims = ARRAY_DIMENSIONS.get(key)
        if dims is None or len(dims) != value.ndim:
            dims = dimension_names(value.shape, spec, sizes)
        variables[key] = xarray.Variable(dims, value,
                                         {"unit": unit, "description": description})
    coords = {name: variables.pop(c) for name, c in spec
              if c in variables and variables[c].dims == (name,)}
    return xarray.Dataset(variables, coords={f"{n}": v for n, v in coords.items()},
                          attrs={k: v for k, v in attrs.items() if np.ndim(v) == 0})


def run_dataset(summary, columns, attrs, n_rings):
    """A run's /summary: dimensions step (coordinate 0, 1, ...) and ring."""
    import numpy as np
    ds = xarray_dataset(summary, columns, [("step", None), ("ring", None)], attrs)
    n = len(next(iter(summary.values())))
    return ds.assign_coords(step=np.arange(n),
                            **({"ring": np.arange(1, n_rings + 1)} if "ring" in ds.dims else {}))


def run_frame(summary):
    """A run's /summary as a pandas.DataFrame: one row per step, a column per
    dataset (a steps x rings one as name[1], name[2], ...)."""
    import numpy as np
    import pandas
    columns = {}
    for key, value in summary.items():
        if np.ndim(value) == 2:
            for k in range(value.shape[1]):
                columns[f"{key}[{k + 1}]"] = value[:, k]
        else:
            columns[key] = value
    frame = pandas.DataFrame(columns)
    frame.index.name = "step"
    return frame


class RunFile:
    """A run's results file (cdea run, shoot; time runs too) read by
    cdea.load: the reading side of RunResult under the same names."""

    def __init__(self, path, f):
        import numpy as np
        s = f["summary"]
        self.path = os.fspath(path)
        self.summary = cdea_products.datasets(s)
        self.columns = cdea_products.columns(s)
        self.attributes = cdea_products.attributes(s)
        root = cdea_products.attributes(f)
        self.parameters = root.get("parameters", "")
        self.method = root.get("method", "")
        self.status = root.get("run_status", "")
        self.completed = self.status == "complete"
        self.n_steps = len(self.summary["stage"])
        self.n_rings = int(np.shape(self.summary["voltage_kV"])[-1])
        self.field_steps = sorted(int(k) for k in f["steps"]) if "steps" in f else []

    def __len__(self):
        return self.n_steps

    def __repr__(self):
        return (f"<cdea.RunFile {self.method}: {self.n_steps} steps, "
                f"{self.status or 'no status'}: {self.path}>")

    @property
    def onset(self):
        import numpy as np
        a = self.attributes
        if not int(np.ravel(a.get("onset_found", 0))[0]):
            return None
        return {"voltage_kV": np.atleast_1d(a["onset_voltage_kV"]),
                "radius_mm": float(a["onset_radius_mm"]),
                "load_factor": float(a["onset_load_factor"])}

    def fields(self, step):
        """The datasets of /steps/NNNNNN (negative steps count from the end)."""
        if not -self.n_steps <= step < self.n_steps:
            raise IndexError(f"step {step} is not one of the {self.n_steps} steps")
        step %= self.n_steps
        if step not in self.field_steps:
            raise IndexError(f"step {step} has no fields in {self.path} (field_steps)")
        with cdea_products.open_file(self.path) as f:
            return cdea_products.datasets(f[f"steps/{step:06d}"])

    def to_pandas(self):
        """/summary as a pandas.DataFrame (one row per step)."""
        return run_frame(self.summary)

    def to_xarray(self):
        """/summary as an xarray.Dataset (dimensions step, ring)."""
        return run_dataset(self.summary, self.columns, self.attributes, self.n_rings)


class ProductFile(dict):
    """A results file other than a run's, read by cdea.load: a dict of numpy
    arrays keyed by the path in the file ('sweep/frequency_Hz'; a root
    dataset by its name), a complex value's two parts joined (the name
    without _real/_imag); `attributes` the root attributes."""

    def __init__(self, path, kind, f):
        super().__init__()
        self.path, self.kind = os.fspath(path), kind
        self.attributes = cdea_products.attributes(f)
        self.columns = {}
        for group in [""] + [g for g in f if not hasattr(f[g], "shape")]:
            node = f[group] if group else f
            prefix = group + "/" if group else ""
            for key, value in cdea_products.datasets(node).items():
                self[prefix + key] = value
            for key, column in cdea_products.columns(node).items():
                self.columns[prefix + key] = column
        self._join_complex()

    def _join_complex(self):
        for key in [k for k in self if "_real" in k]:
            imag = key.replace("_real", "_imag")
            if imag in self:
                joined = key.replace("_real", "")
                self[joined] = self.pop(key) + 1j * self.pop(imag)
                self.columns[joined] = self.columns.pop(key)
                self.columns.pop(imag)

    def __repr__(self):
        return f"<cdea.ProductFile {self.kind}: {len(self)} arrays: {self.path}>"

    def group(self, name):
        """The arrays of group @p name ('' for the root's) by their names."""
        prefix = name + "/" if name else ""
        return {k[len(prefix):]: v for k, v in self.items()
                if k.startswith(prefix) and "/" not in k[len(prefix):]}

    def to_xarray(self, group=None):
        """The numeric arrays of @p group (default: the product's main one) as
        an xarray.Dataset with named dimensions, units and descriptions."""
        if group is None:  # a fit of material tests keeps its data in /samples
            group = "samples" if "samples/stretch" in self else MAIN_GROUP[self.kind]
        arrays = numeric(self.group(group))
        prefix = group + "/" if group else ""
        columns = {k: self.columns.get(prefix + k, ("", "")) for k in arrays}
        spec = DIMENSIONS[self.kind].get(group, [("row", None)])
        return xarray_dataset(arrays, columns, spec, self.attributes)

    def to_pandas(self, group=None):
        """The arrays of @p group as a pandas.DataFrame (long form over the
        dimensions of the group's xarray.Dataset)."""
        return self.to_xarray(group).to_dataframe()


def load(path):
    """The results file @p path as an object: a RunFile for a run (cdea run,
    shoot, time runs), else a ProductFile (dict of numpy arrays).
    FileNotFoundError if there is no file, ValueError if it is not a results
    file of cdea."""
    with cdea_products.open_file(path) as f:
        kind = cdea_products.kind_of(f)
        if kind is None:
            raise cdea_products.ProductError(
                f"{os.fspath(path)}: not a results file of cdea (none of the groups of a run, "
                "map, optimum, fit, chart, response or frequency sweep)")
        if kind in ("run", "time run"):
            return RunFile(path, f)
        return ProductFile(path, kind, f)


def numeric(arrays):
    """The arrays of numbers (texts have no place in a Dataset's variables)."""
    import numpy as np
    return {k: v for k, v in arrays.items() if np.asarray(v).dtype.kind in "fiuc"}


def sweep_dataset(sweep):
    """A SweepResult as an xarray.Dataset (dimensions rv, outer_voltage, edge)."""
    return xarray_dataset(numeric(sweep.arrays), sweep.columns, DIMENSIONS["map"][""],
                          sweep.attributes)


def extend(module):
    """Adds load, RunFile, ProductFile and the results' to_pandas/to_xarray to
    the compiled module."""
    module.load, module.RunFile, module.ProductFile = load, RunFile, ProductFile
    run = module.RunResult
    run.to_pandas = RunFile.to_pandas
    run.to_xarray = RunFile.to_xarray
    module.SweepResult.to_xarray = sweep_dataset
    module.SweepResult.to_pandas = lambda self: sweep_dataset(self).to_dataframe()
    module.SweepResult.to_pandas.__doc__ = ("the map as a pandas.DataFrame, one row per "
                                            "(rv, outer_voltage, edge)")
