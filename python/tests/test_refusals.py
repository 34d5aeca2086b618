"""Refusals, never a crash or another exception: an object made by __new__ without __init__
(as a stateless pickle makes one), a block of another search or an edited pickled block, a
document that is not UTF-8, a bad per_dimension entry."""

import pickle

import pytest

import linkwright

from test_atlas import SMALL
from test_path_search import POINTS


def uninitialised_uses():
    """Each bound class's object made by __new__ alone, and something that uses it."""
    search = linkwright.PathSearch(POINTS, starts=10)
    return [
        (linkwright.Linkage, lambda o: o.sweep()),
        (linkwright.Linkage, lambda o: o.kind),
        (linkwright.Linkage, lambda o: repr(o)),
        (linkwright.Linkage, lambda o: pickle.dumps(o)),
        (linkwright.Linkage, lambda o: o.tolerance_study(0.1, mc_samples=2)),
        (linkwright.PathSearch, lambda o: o.run()),
        (linkwright.PathSearch, lambda o: o.run_block(0)),
        (linkwright.PathSearch, lambda o: o.blocks),
        (linkwright.PathStartBlock, lambda o: o.kept),
        (linkwright.PathStartBlock, lambda o: search.merge([o])),
        (linkwright.Atlas, lambda o: o.page(0, 1)),
        (linkwright.Atlas, lambda o: o.cells),
        (linkwright.Atlas, lambda o: o.linkage(0)),
    ]


@pytest.mark.parametrize("cls, use", uninitialised_uses())
def test_an_object_made_without_init_is_refused_naming_its_class(cls, use):
    made = cls.__new__(cls)
    name = cls.__name__
    with pytest.raises(TypeError, match=rf"^linkwright\.{name} is not initialised: it was made by {name}\.__new__ "
                                        rf"without __init__ \(make one with linkwright\.{name}\(\.\.\.\), or unpickle "
                                        rf"one\)$"):
        use(made)


def test_unpickling_still_initialises_each_class():
    search = linkwright.PathSearch(POINTS, starts=10)
    for thing in (linkwright.example("thesis-crank-rocker"), search, search.run_block(0), linkwright.Atlas(**SMALL)):
        again = pickle.loads(pickle.dumps(thing))
        assert type(again) is type(thing)
    assert pickle.loads(pickle.dumps(search)).blocks == 1


def test_a_block_of_another_search_is_refused_not_read_past():
    search = linkwright.PathSearch(POINTS, starts=10)
    other = linkwright.PathSearch(POINTS[:4], starts=10)  # fewer targets: its minima have 4 crank angles
    with pytest.raises(linkwright.Error) as refused:
        search.merge([other.run_block(0)])
    assert refused.value.field == "blocks"
    assert str(refused.value) == ("block 0 cannot be merged: it is a block of another search (other targets, timing "
                                  "or options), not of this one")


def test_a_pickled_block_edited_is_refused_with_a_sentence():
    search = linkwright.PathSearch(POINTS, starts=10)
    block = search.run_block(0)
    assert block.kept > 0
    state = block.__getstate__()
    # Its minima's crank angles emptied: __setstate__ takes it, merge() refuses it.
    minima = [m[:10] + ([],) + m[11:] for m in state[5]]
    emptied = linkwright.PathStartBlock.__new__(linkwright.PathStartBlock)
    emptied.__setstate__(state[:5] + (minima,))
    with pytest.raises(linkwright.Error) as refused:
        search.merge([emptied])
    assert refused.value.field == "blocks"
    assert "has 0 crank angles, not one for each of the 6 targets" in str(refused.value)
    # Not a block's state at all: refused by __setstate__, as linkwright.Error.
    for bad in [state[:5], state[:5] + ("minima",), state[:1] + ("fingerprint",) + state[2:],
                state[:5] + ([(1.0, 2.0)],)]:
        made = linkwright.PathStartBlock.__new__(linkwright.PathStartBlock)
        with pytest.raises(linkwright.Error, match=r"^linkwright\.PathStartBlock: not a pickled block"):
            made.__setstate__(bad)


def test_a_document_that_is_not_utf8_is_refused_as_linkwright_error(tmp_path):
    path = tmp_path / "latin1.linkwright"
    path.write_bytes('{"format": "linkwright", "version": 4, "name": "café"}'.encode("latin-1"))
    with pytest.raises(linkwright.Error) as refused:
        linkwright.load(str(path))
    assert "ill-formed UTF-8" in str(refused.value)
    assert "caf\\xE9" in str(refused.value)
    # A path given as bytes that are not UTF-8: the refusal names it, \xNN for the odd byte.
    with pytest.raises(linkwright.Error) as missing:
        linkwright.load(bytes(tmp_path) + b"/\xff.linkwright")
    assert "\\xff.linkwright" in str(missing.value)


@pytest.mark.parametrize("own, shown", [
    ({"crank length": "wide"}, "'crank length': 'wide'"),
    ({"crank length": None}, "'crank length': None"),
    ({"crank length": True}, "'crank length': True"),
    ({"crank length": [0.1]}, "'crank length': [0.1]"),
    ({3: 0.1}, "3: 0.1"),
])
def test_a_bad_per_dimension_entry_is_refused_naming_it(own, shown):
    thesis = linkwright.example("thesis-crank-rocker")
    with pytest.raises(linkwright.Error) as refused:
        thesis.tolerance_study(0.05, mc_samples=2, per_dimension=own)
    assert refused.value.field == "per_dimension[0]"
    assert str(refused.value) == ("per_dimension maps a dimension's name (a str) to its ± (a number, in the length "
                                  "unit); entry 0 is " + shown)
