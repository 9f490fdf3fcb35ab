"""The example notebook (examples/notebooks/lecture.ipynb) runs from start to end on an IPython
kernel (Debian's python3-nbclient, python3-ipykernel) and shows its pictures."""
import os
import pathlib

import nbclient
import nbformat

NOTEBOOK = pathlib.Path("examples/notebooks/lecture.ipynb")


def test_the_example_notebook_runs_and_shows_its_pictures():
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    env_path = os.environ.get("PYTHONPATH", "")  # the kernel inherits it: the module in the build
    assert "python" in env_path
    nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3",
                            resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    outputs = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    pictures = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(pictures) >= 4
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "cutoff 60" in text and "spot factor" in text
