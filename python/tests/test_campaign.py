"""load_campaign on the shipped campaign ch3_ca: one row per member, its swept keys, status,
markers, and the fitted times with their 95 % intervals from report/fits.json."""
import json
import math
import shutil

import h5py
import pytest

import capsule_study as cs


def test_one_row_per_member_with_fits_and_intervals(ch3_ca):
    df = cs.load_campaign(ch3_ca)
    folders = sorted(p.name for p in (ch3_ca / "members").iterdir())
    assert sorted(df["slug"] + "-" + df["member_id"]) == folders and len(df) == 18
    assert (df["status"] == "complete").all()
    assert sorted(df["case"].unique()) == ["2d", "3d"]
    assert sorted(df[df["case"] == "3d"]["resolution.a"].unique()) == [5.0, 7.0]
    assert sorted(df["Ca"].unique()) == [0.0125, 0.025, 0.05, 0.1, 0.2, 0.4]
    fits = {m["id"]: m for m in json.loads((ch3_ca / "report" / "fits.json").read_text())["members"]}
    for _, row in df.iterrows():
        for fit, parameter in (("response", "k_tau_s"), ("recovery", "k_tau_r")):
            p = next(q for q in fits[row["member_id"]]["fits"][fit]["parameters"] if q["name"] == parameter)
            column = f"{fit}.{parameter}"
            assert row[column] == p["value"]
            assert (row[column + ".ci95_low"], row[column + ".ci95_high"]) == tuple(p["ci95"])
            assert row[column + ".ci95_low"] < row[column] < row[column + ".ci95_high"]
        with h5py.File(row["path"], "r") as f:
            for name, value in f["markers"].attrs.items():
                assert row[name] == value or (math.isnan(row[name]) and math.isnan(value))
            assert row["wall_seconds"] == f.attrs["wall_seconds"]


def test_a_campaign_file_finds_its_results(ch3_ca, tmp_path):
    def same(a, b):  # the folder may be named by another path to it
        return a.drop(columns="path").equals(b.drop(columns="path"))

    by_file = cs.load_campaign(ch3_ca / "campaign.json")  # the record beside the results
    assert same(by_file, cs.load_campaign(ch3_ca))
    copy = tmp_path / "elsewhere.json"
    shutil.copy(ch3_ca / "campaign.json", copy)
    assert same(cs.load_campaign(copy, results=ch3_ca.parent), by_file)
    with pytest.raises(FileNotFoundError, match="campaign ch3_ca has no results folder"):
        cs.load_campaign(copy, results=tmp_path)


def test_without_a_report_no_fitted_columns(ch3_ca, tmp_path):
    folder = tmp_path / "ch3_ca"
    shutil.copytree(ch3_ca, folder, ignore=shutil.ignore_patterns("report", "3d-*"))
    df = cs.load_campaign(folder)
    assert len(df) == 6 and (df["case"] == "2d").all()
    assert not [c for c in df.columns if c.startswith(("response", "recovery"))]
    assert df["D_stop"].notna().all()


def test_failed_fits_give_their_reason(top):
    df = cs.load_campaign(top / "results" / "ch4_2d_tumble")
    failed = df[df["double_exponential.reason"].notna()]
    assert len(failed) > 0
    assert failed["double_exponential.reason"].str.contains("covariance").any()
