"""Keyword options as the command line's: one table, the native module's, serves both.

A keyword is the command line's option without its dashes, with underscores:
``azimuth=90`` is ``--azimuth 90``, ``no_diagonals=True`` is ``--no-diagonals``. The values are
checked by the command line's parser, so a bad one raises its message.
"""

import contextlib
import logging
import numbers
import os
import re
import threading

from . import _errors, _native

_OPTIONS = _native.options()
_SUMMARIES = {command["name"]: command["summary"] for command in _native.commands()}
_LOG = logging.getLogger("terrain_sketch")


def keyword(option_name):
    """``--base-slope`` -> ``base_slope``."""
    return option_name.lstrip("-").replace("-", "_")


def _option_named(key):
    for spec in _OPTIONS:
        if keyword(spec["name"]) == key:
            return spec
    return None


def _is_truth(value):
    """True and False, Python's or numpy's (np.bool_ is no bool)."""
    return isinstance(value, bool) or getattr(getattr(value, "dtype", None), "kind", "") == "b"


def _value_text(key, spec, value):
    if _is_truth(value):
        raise ValueError(f"{key} takes {spec['value']}, not {value}")
    if isinstance(value, (tuple, list)) or getattr(value, "ndim", 0) == 1:  # numpy's too
        value = tuple(value)
        # X,Y: its numbers counted (a third one was named as the second's fault). An option of
        # one value takes no list: preview=["a.svg"] was joined into a path of its own.
        parts = spec["value"].count(",") + 1
        if parts == 1:
            raise ValueError(f"{key} takes one {spec['value']}, not a list: {value!r}")
        if len(value) != parts:
            raise ValueError(f"{key} takes {spec['value']}, {parts} numbers, not {value!r}")
        return ",".join(_value_text(key, spec, part) for part in value)
    # numpy's scalars as Python's numbers: numpy 2 gives repr(np.float64(45)) as
    # "np.float64(45.0)", which the parser refused.
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, (os.PathLike, bytes)):
        return os.fsdecode(value)
    return str(value)


def to_arguments(options):
    """The command line's arguments for keyword options; None leaves an option at its default.
    Options unknown here, or of another command, go on too: the parser refuses them by name."""
    arguments = []
    for key, value in options.items():
        spec = _option_named(key)
        if spec is None:
            arguments.append("--" + key.replace("_", "-"))
        elif spec["value"] is None:  # a switch
            if value not in (True, False, None):
                raise ValueError(f"{key} is a switch: pass True or False, not {value!r}")
            if value:
                arguments.append(spec["name"])
        elif value is not None:
            arguments += [spec["name"], _value_text(key, spec, value)]
    return arguments


def path_argument(path):
    """A path (text, bytes or path-like, as open() takes) as an argument that cannot be taken for an
    option."""
    text = os.fsdecode(path)
    return "./" + text if text.startswith("-") else text


def log_line(line):
    """A line the run tells: a warning (a run that drew nothing) as one, every note as info."""
    if line.startswith("warning:"):
        _LOG.warning(line)
    else:
        _LOG.info(line)


def hooks(progress, function=None):
    """What the native run calls back: progress, the notes (the command line's on stderr, here
    the terrain_sketch logger's at INFO, in the words of `function` when one is named: see
    keyword_message), and whether it may catch Ctrl-C (only on Python's main thread)."""
    if progress is not None and not callable(progress):
        raise ValueError("progress must be a callable taking a fraction from 0 to 1")
    main = threading.current_thread() is threading.main_thread()
    return _native.RunHooks(progress, notes_of(function), main)


def notes_of(function):
    """log_line, or log_line in the words of `function` (None: the command line's)."""
    if function is None:
        return log_line
    return lambda line: log_line(keyword_message(line, function))


def keyword_message(text, function):
    """A message of the command line's as the Python function `function` says it (its name as
    called: "silhouettes", "sketch", "dask.silhouettes"): options as keywords, commands as
    functions, its help as help(); "--filter fixed" reads "filter='fixed'"."""
    text = re.sub(r"`terrain-sketch [a-z-]+ --help` lists the options it takes",
                  f"help(terrain_sketch.{function}) lists the keywords it takes", text)
    text = re.sub(r"unknown option '--([^']*)'",
                  lambda match: f"unknown keyword '{keyword(match.group(1))}'", text)

    def other_function(match):
        takers = ", ".join(name.replace("-", "_") + "()" for name in match.group(2).split(", "))
        return f"{function}() does not take {keyword(match.group(1))} (a keyword of {takers})"
    text = re.sub(r"^[a-z-]+ does not take (--[a-z-]+) \(an option of ([a-z, -]+)\)",
                  other_function, text)
    return in_keywords(text)


@contextlib.contextmanager
def keyword_errors(function):
    """Raises the bad options and failed runs of the command line's door in the words of
    `function` (keyword_message)."""
    try:
        yield
    except (ValueError, _errors.Error) as error:
        said = keyword_message(str(error), function)
        if said == str(error):
            raise
        # As the package's own kinds: a subclass may not take a message alone.
        raise (_errors.Error if isinstance(error, _errors.Error) else ValueError)(said) from None


def _is_choice(spec, word):
    """Whether `word` is one of the choices of an option whose value is one (its value named by
    a single letter, F for --filter, the choice named in its help)."""
    value = spec["value"] or ""
    return (len(value) == 1 and value not in "NXKM"
            and re.search(r"\b" + re.escape(word) + r"\b", spec["help"]) is not None)


def in_keywords(text):
    """Help text of the command line's, its options named as keywords: "--every N cells" reads
    "every=N cells", "--adapt-window cells" reads "adapt_window cells", "--filter fixed" reads
    "filter='fixed'"; and what the command line reports on stderr goes to the logger, as the
    notes do."""
    def named(match):
        spec = _option_named(keyword(match.group(1)))
        if spec is None:
            return match.group(0)
        key, then = keyword(spec["name"]), match.group(2) or ""
        if then.strip() == spec["value"]:
            return f"{key}={spec['value']}"
        if then.strip() and then.strip().islower() and _is_choice(spec, then.strip()):
            return f"{key}='{then.strip()}'"
        return key + then
    text = text.replace("on stderr", "to the terrain_sketch logger")
    return re.sub(r"(--[a-z][a-z-]*)( [A-Z][A-Z.,]*\b| [a-z]+\b)?", named, text)


def options_help(command, leave_out=()):
    """The options that `command` takes, as a docstring's section."""
    lines = []
    for spec in _OPTIONS:
        key = keyword(spec["name"])
        if command not in spec["commands"] or key in leave_out:
            continue
        value = spec["value"] or "True/False"
        help_lines = in_keywords(spec["help"]).splitlines()
        lines.append(f"    {key} ({value}): {help_lines[0]}")
        lines += [f"        {more}" for more in help_lines[1:]]
    return "\n".join(lines)


def summary(command):
    return in_keywords(" ".join(_SUMMARIES[command].split()))
