"""The ```python blocks of docs/python.md run, in order, in one namespace, in a temporary directory
(a block right after a `<!-- not run ... -->` line is skipped)."""
import os
import re

import pytest

DOC = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")


def blocks():
    text = open(DOC, encoding="utf-8").read()
    for m in re.finditer(r"(<!-- not run[^\n]*-->\n)?```python\n(.*?)```", text, re.S):
        if not m.group(1):
            yield m.group(2)


def test_python_md_blocks_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code = list(blocks())
    assert len(code) >= 5
    namespace = {}
    for i, block in enumerate(code):
        try:
            exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
        except Exception as e:  # name the block
            pytest.fail(f"docs/python.md python block {i + 1} failed: {e!r}\n{block}")
