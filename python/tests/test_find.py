"""find_members: signac-style queries on the members' scene keys, dotted keys allowed."""
import pytest

import capsule_study as cs


def names(found):
    return sorted(p.name.rsplit("-", 1)[0] for p in found)


def test_equality_on_plain_and_dotted_keys(ch3_ca):
    assert names(cs.find_members(ch3_ca, Ca=0.1)) == ["2d-Ca0.1", "3d-Ca0.1-a5", "3d-Ca0.1-a7"]
    assert names(cs.find_members(ch3_ca, Ca=0.1, resolution__a=7)) == ["3d-Ca0.1-a7"]
    assert names(cs.find_members(ch3_ca, {"resolution.a": 7, "Ca": 0.1})) == ["3d-Ca0.1-a7"]
    assert cs.find_members(ch3_ca, Ca=0.3) == []
    assert cs.find_members(ch3_ca, no_such_key=1) == []


def test_operators(ch3_ca):
    assert names(cs.find_members(ch3_ca, {"dim": 3, "Ca": {"$gte": 0.2}, "resolution.a": {"$lt": 6}})) == \
        ["3d-Ca0.2-a5", "3d-Ca0.4-a5"]
    assert len(cs.find_members(ch3_ca, Ca={"$in": [0.0125, 0.4]})) == 6
    assert len(cs.find_members(ch3_ca, dim={"$ne": 2})) == 12
    assert len(cs.find_members(ch3_ca, {"resolution.a": {"$exists": True}})) == 18
    with pytest.raises(ValueError, match=r"unknown operator \$near on Ca"):
        cs.find_members(ch3_ca, Ca={"$near": 0.1})


def test_the_results_root_searches_every_campaign(ch3_ca):
    found = cs.find_members(ch3_ca.parent, Ca=0.1, resolution__a=7, dim=3)
    assert ch3_ca / "members" in [p.parent for p in found]
    assert len({p.parent.parent for p in found}) > 1  # other campaigns ran this scene key too
