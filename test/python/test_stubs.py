"""The type stubs python/pccd/_pccd.pyi (installed next to the module, with py.typed): they parse,
name every public attribute of the module and of its classes (Object, Result and the proximity
queries' results), and nothing that does not exist; the functions' parameters match the module's
signatures where pybind11 states them."""

import ast
import pathlib

import pccd
import pccd._pccd as compiled


def public(names):
    names = set(names)
    return {n for n in names if not n.startswith("_")} | ({"__version__"} & names)


def stub_tree():
    path = pathlib.Path(compiled.__file__).with_name("_pccd.pyi")
    assert path.is_file(), f"{path} is missing: the stubs are not installed next to the module"
    assert path.with_name("py.typed").is_file()
    return ast.parse(path.read_text())


def stub_names(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = node
    return names


def class_members(node, names=None):
    """The methods and properties a stubbed class defines, with those of its stubbed bases."""
    members = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
    for base in node.bases:
        if names is not None and isinstance(base, ast.Name) and base.id in names:
            members |= class_members(names[base.id], names)
    return members


def test_the_stubs_name_every_public_attribute_and_nothing_else():
    names = stub_names(stub_tree())
    module = public(dir(compiled))
    stubbed = public(n for n in names if not n.startswith("_") or n == "__version__")
    assert module - stubbed == set(), f"not in the stubs: {sorted(module - stubbed)}"
    assert stubbed - module == set(), f"in the stubs only: {sorted(stubbed - module)}"
    assert set(pccd.__all__) <= stubbed
    for cls in (compiled.Object, compiled.LeanObject, compiled.Result, compiled.DistanceResult, compiled.ClearanceResult,
                compiled.ContactResult, compiled.Contact, compiled.World, compiled.WorldHandle,
                compiled.ContactTimeResult, compiled.ClearanceProfile):
        members = public(dir(cls))
        stubbed_members = {m for m in class_members(names[cls.__name__], names) if not m.startswith("_")}
        assert members - stubbed_members == set(), f"{cls.__name__}: not in the stubs: {sorted(members - stubbed_members)}"
        assert stubbed_members - members == set(), f"{cls.__name__}: in the stubs only: {sorted(stubbed_members - members)}"


def test_the_stubbed_parameters_are_the_modules():
    names = stub_names(stub_tree())
    for name in ("read_points", "write_points", "orthonormalize", "pair_seed", "do_intersect", "intersection_points",
                 "distance", "within_distance", "contacts", "clearance", "time_of_contact", "time_of_contact_many"):
        node = names[name]
        stubbed = [a.arg for a in node.args.args] + [a.arg for a in node.args.kwonlyargs]
        signature = getattr(compiled, name).__doc__.splitlines()[0]  # pybind11: "name(a: ..., b: ...) -> ..."
        for parameter in stubbed:
            assert f"{parameter}:" in signature, (name, parameter, signature)
    load = [n for n in names["Object"].body if isinstance(n, ast.FunctionDef) and n.name == "load"][0]
    assert [a.arg for a in load.args.args] == ["path"] and [a.arg for a in load.args.kwonlyargs] == ["leaf_size", "volume"]
