"""Table-like results: an aligned text table with units in the header (``print(result)``,
``repr``, :meth:`TableResult.table`) and a pandas DataFrame (:meth:`TableResult.to_frame`;
pandas is optional and imported only there).

A result type is a namedtuple subclass with :class:`TableResult` first among its bases and
``_COLUMNS``, a tuple of (field, header, unit) triples; a field whose value is not 1-d (a
spectrum over dampings and periods) overrides :meth:`TableResult._table_columns`. Numbers
are written with ``digits`` significant digits in the style of C's ``%.{digits}g`` (as the
driver's text tables), ``nan``, ``inf``, ``-inf`` as such; the DataFrame holds the full
float64 values.
"""

import numpy as np

from . import _core

#: Rows shown by print() and repr(); longer tables show their head and tail.
MAX_ROWS = 60


def format_number(x, digits=6):
    """One cell: an int as it is, a real with `digits` significant digits (%g style), a
    string unchanged."""
    if isinstance(x, (str, np.str_)):
        return str(x)
    if isinstance(x, (bool, np.bool_)):
        return str(bool(x))
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if x is None:
        return ""
    return f"{float(x):.{digits}g}"


def format_table(columns, digits=6, max_rows=None, notes=()):
    """An aligned text table.

    columns: a list of (header, unit, values) with values 1-d and of one length; the
    header line is ``header (unit)`` (``header`` alone for unit ''). Text columns are
    left-aligned, numbers right-aligned. max_rows (None: all) keeps the first and last
    rows of a longer table with a ``...`` line between. notes: lines printed below."""
    heads = [f"{h} ({u})" if u else h for h, u, _ in columns]
    nrows = len(columns[0][2]) if columns else 0
    rows = list(range(nrows))
    cut = None
    if max_rows is not None and nrows > max_rows:
        half = max(max_rows // 2, 1)
        rows = rows[:half] + rows[-half:]
        cut = half
    cells, left = [], []
    for (_, _, values), head in zip(columns, heads):
        text = [format_number(values[i], digits) for i in rows]
        cells.append(text)
        left.append(any(isinstance(values[i], (str, np.str_)) for i in rows))
    widths = [max([len(h)] + [len(c) for c in col]) for h, col in zip(heads, cells)]

    def line(items):
        return "  ".join(s.ljust(w) if lft else s.rjust(w)
                         for s, w, lft in zip(items, widths, left)).rstrip()

    out = [line(heads)]
    for k in range(len(rows)):
        if cut is not None and k == cut:
            out.append(line(["..."] * len(heads)))
        out.append(line([col[k] for col in cells]))
    if cut is not None:
        out.append(f"[{nrows} rows; .table() shows all, .to_frame() gives a DataFrame]")
    out.extend(notes)
    return "\n".join(out)


class TableResult:
    """Mixin of the table-like namedtuple results (listed first among the bases)."""

    __slots__ = ()
    #: (field, header, unit) of each column, in order
    _COLUMNS = ()

    def _table_columns(self):
        """[(header, unit, 1-d values)]: the fields of _COLUMNS, flattened; fields that are
        None (not computed) are left out."""
        cols = []
        for field, head, unit in self._COLUMNS:
            value = getattr(self, field)
            if value is None:
                continue
            if isinstance(value, (tuple, list)) and value and isinstance(value[0], str):
                cols.append((head, unit, list(value)))
            else:
                cols.append((head, unit, np.asarray(value, dtype=np.float64).reshape(-1)))
        return cols

    def _table_notes(self):
        """Lines printed under the table (scalar fields, what was left out)."""
        return []

    def _frame_attrs(self):
        """{name: value} stored in DataFrame.attrs besides the units."""
        return {}

    def table(self, digits=6, max_rows=None):
        """The result as an aligned text table (str): one column per quantity, its unit in
        the header; numbers with ``digits`` significant digits; all rows unless
        ``max_rows`` is given."""
        return format_table(self._table_columns(), digits=digits, max_rows=max_rows,
                            notes=self._table_notes())

    def __str__(self):
        return self.table(max_rows=MAX_ROWS)

    def __repr__(self):
        return f"{type(self).__name__}:\n{self.table(max_rows=MAX_ROWS)}"

    def to_frame(self):
        """The table as a pandas DataFrame (pandas is an optional dependency: ImportError
        naming it when it is missing). Columns are named as in the printed header without
        the unit; ``frame.attrs['units']`` maps each column to its unit."""
        pd = _core.optional_import("pandas", f"{type(self).__name__}.to_frame()")
        cols = self._table_columns()
        frame = pd.DataFrame({head: values for head, _, values in cols})
        frame.attrs["units"] = {head: unit for head, unit, _ in cols}
        frame.attrs.update(self._frame_attrs())
        return frame
