"""docs/python.md's examples run as written, and print what the page says they print."""
import re
import subprocess
import sys

import pytest


def examples(source_dir):
    """Each ```python block of docs/python.md, with the output the text after it promises ("It prints `...`")."""
    text = (source_dir / "docs" / "python.md").read_text()
    found = []
    for match in re.finditer(r"```python\n(.*?)```\n(.*?)(?=```|\Z)", text, re.S):
        promised = re.search(r"It prints `([^`]*)`", match[2])
        found.append((match[1], promised[1] if promised else None))
    return found


def test_the_page_has_its_examples(source_dir):
    assert len(examples(source_dir)) == 2


@pytest.mark.parametrize("index", [0, 1])
def test_an_example_runs_and_prints_what_the_page_says(index, source_dir, work):
    code, promised = examples(source_dir)[index]
    # The examples run from the repository's root: the scenes, and out/ for what they write.
    (work / "assets").symlink_to(source_dir / "assets")
    result = subprocess.run([sys.executable, "-c", code], cwd=work, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    if promised is not None:
        assert result.stdout.strip() == promised
    if index == 0:
        assert (work / "out" / "ward_sweep.png").stat().st_size > 0
