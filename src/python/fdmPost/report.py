"""Markdown reports of the validations and benchmarks."""


def write_markdown(path, lines):
    """Write lines (one string each) to path as a markdown file and echo
    them on standard output, as every report does."""
    text = "\n".join(lines)
    with open(path, "w") as f:
        f.write(text + "\n")
    print(text)
