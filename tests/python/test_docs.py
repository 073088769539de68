"""Every Python example of the README and docs/ runs as written, saved as a file and run as a script (the way a
reader runs it: a farm example without the `__main__` guard used to fail only then), and prints what its page
says it prints. A block is left out only when the line before it says `<!-- docs-test: REASON -->`."""
import re
import subprocess
import sys

SKIP = re.compile(r"<!-- docs-test: ([^>]*) -->\s*$")


def pages(source_dir):
    return [source_dir / "README.md", *sorted((source_dir / "docs").glob("*.md"))]


def examples(source_dir):
    """(page, index, code, promised output or None, skip reason or None) for each ```python block."""
    found = []
    for page in pages(source_dir):
        text = page.read_text()
        blocks = list(re.finditer(r"```python\n(.*?)```\n", text, re.S))
        for index, block in enumerate(blocks):
            following = text[block.end():blocks[index + 1].start() if index + 1 < len(blocks) else len(text)]
            promised = re.search(r"It prints `([^`]*)`", following.split("```")[0])
            skip = SKIP.search(text[:block.start()])
            found.append((page.relative_to(source_dir).as_posix(), index, block[1], promised[1] if promised else None,
                          skip[1] if skip else None))
    return found


def test_the_pages_have_their_examples(source_dir):
    found = examples(source_dir)
    by_page = {}
    for page, *_ in found:
        by_page[page] = by_page.get(page, 0) + 1
    assert by_page.get("docs/python.md") == 4 and by_page.get("docs/farm.md") == 2 and by_page.get("README.md") == 1
    skipped = [(page, reason) for page, _, _, _, reason in found if reason]
    assert skipped == [("docs/farm.md", "needs a Slurm cluster")], skipped


def test_every_example_runs_as_a_script_and_prints_what_its_page_says(source_dir, work):
    # The examples run from the repository's root: the scenes, and out/ for what they write.
    (work / "assets").symlink_to(source_dir / "assets")
    ran = 0
    for page, index, code, promised, skip in examples(source_dir):
        if skip:
            continue
        script = work / f"{page.replace('/', '_')}_{index}.py"
        script.write_text(code)
        result = subprocess.run([sys.executable, script.name], cwd=work, capture_output=True, text=True, timeout=600)
        assert result.returncode == 0, f"{page} example {index}:\n{result.stderr[-3000:]}"
        if promised is not None:
            assert result.stdout.strip() == promised, f"{page} example {index}"
        ran += 1
    assert ran == 6
    assert (work / "out" / "ward_sweep.png").stat().st_size > 0  # docs/python.md's sheet
    assert (work / "out" / "denoised.png").stat().st_size > 0  # docs/python.md's denoising
    assert len(list((work / "out").glob("ct_m*.exr"))) == 4  # docs/farm.md's renders
