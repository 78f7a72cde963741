"""Checks of the numeric arguments of the public functions of yade_rbsm: one place for "finite, in
range" and "a whole number of steps", so that a bad argument raises ValueError naming the function
and the argument instead of looping forever (``check=0``) or silently switching a criterion off
(``d_fail=nan``)."""
import math
import numbers

__all__ = ["number", "count", "flag", "body_ids"]


def number(where, name, value, low=None, high=None, low_open=False, high_open=False):
    """*value* as a float if it is a finite real in the range [low, high] (ends excluded with
    low_open / high_open; None: no bound), else ValueError "where: name must be ... (got value)"."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise ValueError("%s: %s must be a finite number (got %r)" % (where, name, value))
    v = float(value)
    if (low is not None and (v < low or (low_open and v == low))) or (high is not None and (v > high or (high_open and v == high))):
        lo = "" if low is None else ("(" if low_open else "[") + "%g" % low
        hi = "" if high is None else "%g" % high + (")" if high_open else "]")
        raise ValueError("%s: %s must be in %s, %s (got %r)" % (where, name, lo or "(-inf", hi or "inf)", value))
    return v


def count(where, name, value, low=1):
    """*value* as an int if it is a whole number >= low, else ValueError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        if isinstance(value, numbers.Real) and math.isfinite(value) and float(value).is_integer():
            value = int(value)
        else:
            raise ValueError("%s: %s must be a whole number >= %d (got %r)" % (where, name, low, value))
    if value < low:
        raise ValueError("%s: %s must be a whole number >= %d (got %r)" % (where, name, low, value))
    return int(value)


def flag(where, name, value):
    """*value* if it is True or False (numpy's bool too), else ValueError naming it: "no" is a true string,
    and settle(density_scaling="no") ran with the scaling on."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    raise ValueError("%s: %s must be True or False (got %r)" % (where, name, value))


def body_ids(where, ids):
    """*ids* (an iterable of body ids, not a string) as a set of ints, else ValueError naming the entry
    that is not a whole number >= 0 (5.7 or "12" are not ids)."""
    if isinstance(ids, (str, bytes)) or not hasattr(ids, "__iter__"):
        raise ValueError("%s: ids must be a list of body ids (got %r)" % (where, ids))
    return {count(where, "every id", i, low=0) for i in ids}
