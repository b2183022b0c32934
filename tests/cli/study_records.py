"""What the command-line study tests compare: a study directory's evaluations."""
import json
import os


def records(directory):
    """The evaluations by index, without their wall times."""
    out = {}
    with open(os.path.join(directory, "evaluations.jsonl")) as f:
        for line in f:
            r = json.loads(line)
            r.pop("seconds")
            out[r["index"]] = r
    return out
