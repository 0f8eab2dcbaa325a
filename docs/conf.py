"""Sphinx configuration of the hsbearing documentation (``make docs``; MyST Markdown + autodoc + sphinx-gallery)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import hsbearing  # noqa: E402

project = "hsbearing"
author = "hsbearing developers"
copyright = "2026, hsbearing developers"
release = hsbearing.__version__
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinxarg.ext",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = [
    "_build",
    "Thumbs.db",
    ".DS_Store",
    "auto_examples/*.ipynb",
    "auto_examples/*.py",
    "auto_examples/*.zip",
    "auto_examples/*.md5",
    "auto_examples/*.json",
    "figures/*.py",
    "figures/*.jsonl",
]

# MyST: headings get anchors (links like page.md#section resolve), $...$ maths, definition lists.
myst_enable_extensions = ["dollarmath", "deflist", "colon_fence"]
myst_heading_anchors = 4
# The hand-written pages link to source files outside docs/ (code, tests, benchmarks): those are not documents.
# They are shown as plain links to the repository, not treated as cross-references.
myst_url_schemes = {"http": None, "https": None, "mailto": None}

autosummary_generate = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_typehints = "description"
autodoc_mock_imports: list[str] = []
napoleon_numpy_docstring = True
napoleon_google_docstring = False

# Examples: executed only when HSBEARING_DOCS_RUN_EXAMPLES=1 (the slow test tier runs every script;
# the default `make docs` renders them without running them, so the build stays within a few minutes).
_run_examples = os.environ.get("HSBEARING_DOCS_RUN_EXAMPLES") == "1"
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "plot_gallery": _run_examples,
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
}

html_theme = "alabaster"
html_title = f"hsbearing {release}"
html_static_path: list[str] = []
html_theme_options = {"description": "Dynamics and friction of rolling ball bearings", "page_width": "1100px"}

# Header-level jumps in the long hand-written pages are not errors of the docs site; nor is a short name
# (an attribute ``K``) that two classes share; nor that sphinx-argparse's domain cannot answer "any" lookups.
suppress_warnings = ["myst.header", "ref.python", "myst.domains"]

# -n (nitpicky) checks every cross-reference between the pages (MyST links, :doc:, :ref:, figures) -- a broken
# one fails the build -- but not the Python-domain references inside docstrings: their numpydoc types carry
# units ("float, Pa s", "array_like, m"), not class names, and they name private helpers the reference leaves
# out.  tools/check_docs_links.py then checks every relative link and anchor of the built HTML.
nitpick_ignore_regex = [(r"py:.*", r".*")]


def _escape_substitutions(app, what, name, obj, options, lines):
    """Docstrings write |x| for an absolute value; reStructuredText would read a substitution."""
    for i, line in enumerate(lines):
        if "|" in line and not line.lstrip().startswith(("|", "+", ">>>", "...")):
            lines[i] = line.replace("|", "\\|")


def setup(app):
    app.connect("autodoc-process-docstring", _escape_substitutions)
