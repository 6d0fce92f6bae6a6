"""Read the capsule study toolkit's results: member files into xarray, campaigns into pandas
(README.md of this folder; the file format: docs/guide/member-files.md)."""
from .campaign import find_members, load_campaign, results_folder
from .member import Member, load_member
from .quantities import MARKERS, SERIES, SHAPES

__all__ = ["Member", "load_member", "load_campaign", "find_members", "results_folder", "SERIES", "MARKERS", "SHAPES"]
