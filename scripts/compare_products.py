"""Compare two folders of scripts/product_outputs.sh, case by case: every HDF5
file object by object (groups, datasets and attributes: names, types, shapes,
values bit for bit, the `unit` and `description` texts), every other file
byte for byte, the printed output (wall times masked) and exit codes, and the
Python results key by key (arrays bit for bit).

    /usr/bin/python3 scripts/compare_products.py OLD_DIR NEW_DIR

Prints one line per case (OK, or the first differences) and a last line with
the counts; exits 1 if anything differs.
"""
import os
import pickle
import re
import sys

import h5py
import numpy as np

LIMIT = 8  # differences listed per case
# Attributes and datasets that hold wall times differ between any two runs.
TIMED = ("seconds",)


def masked(value, folders):
    """A text with the case folders (which name the output directory) and
    object addresses masked."""
    if isinstance(value, bytes):
        value = value.decode("utf-8", "replace")
    if isinstance(value, str):
        for folder in folders:
            value = value.replace(folder, "<case>")
        value = re.sub(r" at 0x[0-9a-f]+", " at <address>", value)
    return value


def same_array(a, b, folders=()):
    if isinstance(a, (str, bytes)) and isinstance(b, (str, bytes)):
        return masked(a, folders) == masked(b, folders)
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    if a.dtype.kind in "OSUV":
        return a.tolist() == b.tolist()
    return a.tobytes() == b.tobytes()


def attribute_differences(path, old, new, folders):
    out = []
    for name in sorted(set(old.attrs) | set(new.attrs)):
        if name in TIMED:
            continue
        if name not in new.attrs:
            out.append(f"{path}@{name}: only in the old file")
        elif name not in old.attrs:
            out.append(f"{path}@{name}: only in the new file")
        elif not same_array(old.attrs[name], new.attrs[name], folders):
            out.append(f"{path}@{name}: {old.attrs[name]!r:.120} -> {new.attrs[name]!r:.120}")
    return out


def hdf5_differences(old_path, new_path, folders):
    out = []
    with h5py.File(old_path, "r") as old, h5py.File(new_path, "r") as new:
        names_old, names_new = set(), set()
        old.visit(names_old.add)
        new.visit(names_new.add)
        for name in sorted(names_old ^ names_new):
            out.append(f"/{name}: only in the {'old' if name in names_old else 'new'} file")
        out += attribute_differences("/", old, new, folders)
        for name in sorted(names_old & names_new):
            a, b = old[name], new[name]
            if isinstance(a, h5py.Dataset) != isinstance(b, h5py.Dataset):
                out.append(f"/{name}: a group in one file, a dataset in the other")
                continue
            timed = name.rsplit("/", 1)[-1] in TIMED
            if isinstance(a, h5py.Dataset) and not timed and not same_array(a[()], b[()], folders):
                out.append(f"/{name}: values differ ({a.dtype}{a.shape} -> {b.dtype}{b.shape})")
            out += attribute_differences("/" + name, a, b, folders)
    return out


def value_differences(path, old, new, folders=()):
    if isinstance(old, dict) and isinstance(new, dict):
        out = []
        for key in sorted(set(old) | set(new), key=str):
            if key not in new or key not in old:
                out.append(f"{path}[{key!r}]: only in the {'old' if key in old else 'new'} result")
            else:
                out += value_differences(f"{path}[{key!r}]", old[key], new[key], folders)
        return out
    if isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            return [f"{path}: {len(old)} items -> {len(new)}"]
        return [d for i, (a, b) in enumerate(zip(old, new))
                for d in value_differences(f"{path}[{i}]", a, b, folders)]
    if isinstance(old, np.ndarray) or isinstance(new, np.ndarray):
        return [] if same_array(old, new) else [f"{path}: arrays differ"]
    if type(old) is not type(new):
        return [f"{path}: {type(old).__name__} -> {type(new).__name__}"]
    if isinstance(old, str):
        same = masked(old, folders) == masked(new, folders)
    elif isinstance(old, float):
        same = np.float64(old).tobytes() == np.float64(new).tobytes()
    else:
        same = old == new
    return [] if same else [f"{path}: {old!r:.120} -> {new!r:.120}"]


def case_differences(old_dir, new_dir):
    out = []
    folders = (os.path.abspath(old_dir), os.path.abspath(new_dir))
    files_old, files_new = set(), set()
    for root, files in ((old_dir, files_old), (new_dir, files_new)):
        for folder, _, names in os.walk(root):
            for n in names:
                files.add(os.path.relpath(os.path.join(folder, n), root))
    for name in sorted(files_old ^ files_new):
        out.append(f"{name}: only in the {'old' if name in files_old else 'new'} folder")
    for name in sorted(files_old & files_new):
        a, b = os.path.join(old_dir, name), os.path.join(new_dir, name)
        if name.endswith(".h5"):
            out += [f"{name} {d}" for d in hdf5_differences(a, b, folders)]
        elif name.endswith(".pickle"):
            with open(a, "rb") as fa, open(b, "rb") as fb:
                out += value_differences("python", pickle.load(fa), pickle.load(fb), folders)
        elif name == "python.txt":
            continue
        else:
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if masked(fa.read(), folders) != masked(fb.read(), folders):
                    out.append(f"{name}: the texts differ")
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare_products.py OLD_DIR NEW_DIR")
    old, new = sys.argv[1:3]
    cases = sorted(name for name in set(os.listdir(old)) | set(os.listdir(new))
                   if os.path.isdir(os.path.join(old, name)) or os.path.isdir(os.path.join(new, name)))
    failed = 0
    for case in cases:
        if not (os.path.isdir(os.path.join(old, case)) and os.path.isdir(os.path.join(new, case))):
            print(f"{case:30} only in {'the old' if os.path.isdir(os.path.join(old, case)) else 'the new'} folder")
            failed += 1
            continue
        differences = case_differences(os.path.join(old, case), os.path.join(new, case))
        if differences:
            failed += 1
            print(f"{case:30} {len(differences)} differences")
            for d in differences[:LIMIT]:
                print("    " + d)
        else:
            print(f"{case:30} OK")
    print(f"{len(cases) - failed} of {len(cases)} cases identical")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
