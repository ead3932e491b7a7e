"""The strokes of a sketch as columns of numpy arrays."""

import json


class Strokes:
    """Strokes as columns: stroke ``k``'s points are ``x[offsets[k]:offsets[k + 1]]`` (and ``y``,
    and ``m``, the weight of each point of a drawn stroke, written as M in vector files; None for
    exact strokes). ``strokes[k]`` gives them as an array, and iterating gives each stroke's in
    turn. ``columns`` holds the attributes, one array per field, named and ordered as the vector
    outputs' fields (``class``, ``cells``, ``length``, ...; NaN for null). ``statistics`` is the
    run's stage statistics as a dict, ``crs`` the DEM's CRS as WKT ("" for none)."""

    def __init__(self, native):
        self.x = native["x"]
        self.y = native["y"]
        self.m = native["m"]
        self.offsets = native["offsets"]
        import numpy as np  # here, so that the file functions need no numpy

        # The class column as text at any length: an empty list reads as floats, which equal no
        # class name.
        self.columns = {name: np.asarray(values, dtype=str if name == "class" else None)
                        for name, values in native["columns"].items()}
        self.crs = native["crs"]
        self.statistics = json.loads(native["statistics"])

    def __len__(self):
        return len(self.offsets) - 1

    def __getitem__(self, k):
        """Stroke ``k``'s points, as ``coordinates(k)``."""
        return self.coordinates(k)

    def __iter__(self):
        """Each stroke's points in turn, as ``coordinates(k)``."""
        return (self.coordinates(k) for k in range(len(self)))

    def __repr__(self):
        factual = int((self.columns["class"] == "factual").sum())
        return f"<Strokes: {factual} factual, {len(self) - factual} formulated>"

    def coordinates(self, k):
        """Stroke ``k``'s points as an (n, 2) array, or (n, 3) with its weights as a third column
        for drawn strokes. ``k`` counts from 0, or back from the last at -1, as a list's index."""
        import operator

        import numpy as np

        index = operator.index(k)  # a whole number: 1.5 is no stroke
        if not -len(self) <= index < len(self):
            raise IndexError(f"stroke {index} is none of the {len(self)} strokes")
        index %= len(self)  # -1 read offsets[-1]:offsets[0], an empty stroke
        start, end = self.offsets[index], self.offsets[index + 1]
        parts = [self.x[start:end], self.y[start:end]]
        if self.m is not None:
            parts.append(self.m[start:end])
        return np.column_stack(parts)

    def to_geodataframe(self):
        """A geopandas GeoDataFrame: a LineString per stroke with its attributes, and for drawn
        strokes a ``weights`` column holding each point's weight (shapely keeps no M)."""
        import geopandas
        import numpy as np
        from shapely.geometry import LineString

        points = np.column_stack([self.x, self.y])
        lines = [LineString(points[self.offsets[k]:self.offsets[k + 1]]) for k in range(len(self))]
        data = dict(self.columns)
        if self.m is not None:
            data["weights"] = [self.m[self.offsets[k]:self.offsets[k + 1]]
                               for k in range(len(self))]
        return geopandas.GeoDataFrame(data, geometry=lines, crs=self.crs or None)
