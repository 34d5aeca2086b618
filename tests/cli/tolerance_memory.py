"""tolerance's peak memory does not grow with the grid (issue 56): a study over 4·10⁵ inputs,
which held about 1.2 GB when every input's sensitivities were kept (3 KB an input for a
four-bar; 10⁷ inputs reached 24 GB and were killed), runs in under 100 MB, and its figures are
those of the same study with the band kept (-o), which holds the grid whole. The peak resident
set is the child's, from getrusage."""
import json
import os
import resource
import subprocess
import sys
import tempfile

cli = sys.argv[1]
study = ["tolerance", "--fourbar", "60,25,70,45", "--tolerance", "0.1", "--mc-samples", "1", "--json"]
ran = subprocess.run([cli, *study, "--samples", "400000"], capture_output=True, text=True)
peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
assert ran.returncode == 0, ran.stderr
streamed = json.loads(ran.stdout)
assert streamed["inputs"] == 400000, streamed["inputs"]
print(f"peak resident set over 400000 inputs: {peak_mb:.1f} MB")
assert peak_mb < 100, f"peak resident set {peak_mb:.1f} MB over 400000 inputs, expected under 100 MB"

# A band over more inputs than it may hold is refused, naming -o, the bound and the inputs.
with tempfile.TemporaryDirectory() as folder:
    refused = subprocess.run([cli, *study, "--samples", "400000", "-o", os.path.join(folder, "band.csv")],
                             capture_output=True, text=True)
    assert refused.returncode == 2, refused.returncode
    assert "-o: a band kept at every input holds 12 columns' nominal, lowest and highest values there: at most " \
           "166666 inputs for this linkage (got 400000)" in refused.stderr, refused.stderr
    # Within it, the streamed study's figures are those of the band kept whole.
    small = [cli, *study, "--samples", "20000"]
    kept = subprocess.run([*small, "-o", os.path.join(folder, "band.csv")], capture_output=True, text=True)
    alone = subprocess.run(small, capture_output=True, text=True)
    assert kept.returncode == 0 and alone.returncode == 0, kept.stderr + alone.stderr
    assert kept.stdout == alone.stdout
print("passed")
