"""Fills i18n/terrain_sketch_de.ts with the German translation (run after `update-translations`).

    /usr/bin/python3 i18n/translate_de.py
A source text without a German entry here stays unfinished and the script says which.
"""
import os
import sys
import xml.etree.ElementTree as ET

GERMAN = {
    "No strokes: no cell of the DEM is hidden, and none slopes away from the viewer gently enough to be seen once tilted (under the base slope of %L1 % over the exaggeration of %L2, %L3 %): the DEM is flat, or faces the viewer everywhere. Another view azimuth or a larger base slope brings slopes into sight.":
        "Keine Striche: keine Zelle des DGM ist verdeckt, und keine fällt vom Betrachter so sanft ab, dass sie nach dem Kippen zu sehen ist (unter der Grundneigung von %L1 % geteilt durch die Überhöhung von %L2, %L3 %): das DGM ist flach oder überall dem Betrachter zugewandt. Eine andere Blickrichtung oder eine größere Grundneigung bringt Hänge in Sicht.",
    "No strokes: every cell of the DEM is nodata (its declared nodata value, NaN, or a height of 1e30 or more): check the band, the no data value the layer or its file declares (Layer Properties > Transparency), and the band's scale.":
        "Keine Striche: jede Zelle des DGM ist NoData (sein angegebener NoData-Wert, NaN oder eine Höhe von 1e30 oder mehr): prüfen Sie das Band, den NoData-Wert, den der Layer oder seine Datei angibt (Layereigenschaften > Transparenz), und die Skalierung des Bands.",
    "%1 keeps no M values, so the drawn strokes' weights (their taper and depth, which the styles draw) are left out; GeoPackage, FlatGeobuf, Shapefile or CSV keep them.":
        "%1 speichert keine M-Werte, daher entfallen die Gewichte der gezeichneten Striche (ihre Verjüngung und Tiefe, die die Stile zeichnen); GeoPackage, FlatGeobuf, Shapefile oder CSV behalten sie.",
    "No strokes: the slope filter removed every candidate cell, and no cell is hidden. Lower cut-offs keep more, or the slope filter adapted to the DEM scales them.":
        "Keine Striche: der Neigungsfilter hat jede Kandidatenzelle entfernt, und keine Zelle ist verdeckt. Niedrigere Grenzwerte behalten mehr, oder der an das DGM angepasste Neigungsfilter skaliert sie.",
    "No strokes: every chain was shorter than the shortest stroke kept. Drawn for 1:%1, strokes under %L2 mm on paper, or outlining under %L3 m of relief, are dropped too: a larger scale (a smaller number) keeps more.":
        "Keine Striche: jede Kette war kürzer als der kürzeste behaltene Strich. Gezeichnet für 1:%1 entfallen auch Striche unter %L2 mm auf dem Papier oder solche, die weniger als %L3 m Relief umreißen: ein größerer Maßstab (eine kleinere Zahl) behält mehr.",
    "No strokes: every chain was shorter than the shortest stroke kept (%L1 cells). A lower minimum stroke length keeps more.":
        "Keine Striche: jede Kette war kürzer als der kürzeste behaltene Strich (%L1 Zellen). Eine geringere Mindestzahl Zellen je Strich behält mehr.",
    "Tapered line (Terrain Sketch)": "Verjüngte Linie (Terrain Sketch)",
    "<h3>terrain_sketch_draws_taper()</h3><div>True while the Terrain Sketch plugin is loaded and draws the width of every vertex of drawn strokes. Its styles' stepped lines are enabled only where it is unknown.</div>":
        "<h3>terrain_sketch_draws_taper()</h3><div>Wahr, solange die Erweiterung Terrain Sketch geladen ist und die Breite jedes Stützpunkts gezeichneter Striche zeichnet. Die gestuften Linien ihrer Stile sind nur dort aktiv, wo die Funktion unbekannt ist.</div>",
    "Panorama exaggeration": "Überhöhung des Panoramas",
    "How many times as tall as its azimuths are wide the Panorama layer draws its elevation angles, 1 to 50. 0, the default, chooses up to 5 so that a wide field of view is no flat strip. The Panorama layout draws it so.":
        "Wie viel Mal so hoch, wie seine Azimute breit sind, der Panorama-Layer seine Höhenwinkel zeichnet, 1 bis 50. 0, die Voreinstellung, wählt bis zu 5, damit ein weites Blickfeld kein flacher Streifen ist. Das Panorama-Layout zeichnet es so.",
    "%1. Seen from %L2, %L3, %L4 m above the ground, from %L5° to %L6° (azimuths from grid north); elevation angles drawn %7%9. Terrain Sketch %8.":
        "%1. Gesehen von %L2, %L3, %L4 m über dem Boden, von %L5° bis %L6° (Azimute von Gitternord); Höhenwinkel %7 gezeichnet%9. Terrain Sketch %8.",
    "to the same scale as azimuths": "im selben Maßstab wie die Azimute",
    "%L1 times as tall as azimuths are wide": "%L1-mal so hoch, wie Azimute breit sind,",
    "; %L1 samples per cell along each ray": "; %L1 Abtastpunkte je Zelle entlang jedes Strahls",
    "%1 10 mm on the page: %L2° of azimuth.": "%1 10 mm auf der Seite: %L2° Azimut.",
    "Band %1 of the raster's %2 is a colour channel (red, green, blue or alpha) of an image, not heights: choose a DEM.":
        "Band %1 der %2 Bänder des Rasters ist ein Farbkanal (Rot, Grün, Blau oder Alpha) eines Bildes, keine Höhen: wählen Sie ein DGM.",
    "A corner of the raster lies at a coordinate that is not a finite number: its georeferencing is wrong. Set its corners, for example with gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.":
        "Eine Ecke des Rasters liegt bei einer Koordinate, die keine endliche Zahl ist: seine Georeferenzierung ist falsch. Setzen Sie seine Ecken, zum Beispiel mit gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.",
    "The raster's corners lie up to %L1 from the CRS's origin, too far for coordinates to tell a thousandth of its %L2 cells apart: its georeferencing is wrong. Set its corners, for example with gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.":
        "Die Ecken des Rasters liegen bis zu %L1 vom Ursprung des KBS entfernt, zu weit, als dass Koordinaten ein Tausendstel seiner Zellen von %L2 unterscheiden könnten: seine Georeferenzierung ist falsch. Setzen Sie seine Ecken, zum Beispiel mit gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.",
    "%1, band %2": "%1, Band %2",
    "from %L1°": "von %L1°",
    "Factual silhouettes, %1": "Faktische Silhouetten, %1",
    "Formulated silhouettes, %1": "Formulierte Silhouetten, %1",
    "%1. Seen from %L2° (azimuth), vertical exaggeration %L3, base slope %L4 %; %5; %6. Terrain Sketch %7.":
        "%1. Gesehen aus %L2° (Azimut), Überhöhung %L3, Grundneigung %L4 %; %5; %6. Terrain Sketch %7.",
    "%1: row %L2 %, column %L3 %, control point %L4 %": "%1: Zeile %L2 %, Spalte %L3 %, Kontrollpunkt %L4 %",
    "%1. %2 seen from %L3° (azimuth), vertical exaggeration %L4, base slope %L5 %":
        "%1. %2, gesehen aus %L3° (Azimut), Überhöhung %L4, Grundneigung %L5 %",
    "%1, %2": "%1, %2",
    ". Terrain Sketch %1.": ". Terrain Sketch %1.",
    "A drape of %1": "Drapierung von %1",
    "Profile lines": "Profillinien",
    "the thesis's slope filter": "der Neigungsfilter der Dissertation",
    "the slope filter adapted to the DEM": "der an das DGM angepasste Neigungsfilter",
    "drawn strokes": "gezeichnete Striche",
    "drawn strokes for 1:%L1": "gezeichnete Striche für 1:%L1",
    " from the DEM averaged %L1 x %L1 cells": " aus dem DGM, gemittelt über %L1 x %L1 Zellen",
    "Drawn for 1:%L1, the DEM was averaged %L2 x %L2 cells first (to %L3 m a cell, about 0.4 mm on paper): the scale shows nothing finer.":
        "Gezeichnet für 1:%L1: das DGM wurde zuerst über %L2 x %L2 Zellen gemittelt (auf %L3 m je Zelle, etwa 0,4 mm auf dem Papier); feiner zeigt der Maßstab nichts.",
    "Drawn for scale": "Gezeichnet für Maßstab",
    "Drawn strokes: the scale of the map they are drawn for (1:N). The shortest stroke (2 mm on paper), the smoothing, its tolerance and the join gap become at least what that scale needs, strokes outlining less than N/10 000 metres of relief are left out, and the layers' styles draw their widths true at that scale (the renderer's reference scale). A DEM at least twice as fine as the scale needs (cells under 0.4 mm on paper) is first averaged to it. Empty: for no scale; every stroke is still weighed by the relief it outlines.":
        "Gezeichnete Striche: der Maßstab der Karte, für die sie gezeichnet werden (1:N). Der kürzeste Strich (2 mm auf dem Papier), die Glättung, ihre Toleranz und die Verbindungslücke werden mindestens so groß, wie dieser Maßstab es verlangt; Striche, die weniger als N/10 000 Meter Relief umreißen, entfallen, und die Stile der Layer zeichnen ihre Breiten in diesem Maßstab wahr (der Bezugsmaßstab des Renderers). Ein DGM, das mindestens doppelt so fein ist, wie der Maßstab es verlangt (Zellen unter 0,4 mm auf dem Papier), wird zuerst darauf gemittelt. Leer: für keinen Maßstab; jeder Strich wird dennoch nach dem Relief gewichtet, das er umreißt.",
    "the thesis's exact strokes": "die exakten Striche der Dissertation",
    "Internal error: no output set for %1.": "Interner Fehler: keine Ausgabemenge für %1.",
    "%1 must be a GeoTIFF (.tif): %2 is another format.":
        "%1 muss ein GeoTIFF (.tif) sein: %2 hat ein anderes Format.",
    "No cell of the DEM slopes (it is flat, or too few of its cells are valid): the slope filter's cut-offs are scaled by the least, %L1: row %L2 %, column %L3 %, control point %L4 %.":
        "Keine Zelle des DGM ist geneigt (es ist flach, oder zu wenige seiner Zellen sind gültig): die Schwellen des Neigungsfilters werden mit dem kleinsten Faktor skaliert, %L1: Zeile %L2 %, Spalte %L3 %, Kontrollpunkt %L4 %.",
    "Could not apply style %1: %2": "Stil %1 konnte nicht angewendet werden: %2",
    "The input raster layer is not valid.": "Der Eingaberasterlayer ist ungültig.",
    "Band %1 does not exist: the raster has %2 band(s).":
        "Kanal %1 existiert nicht: das Raster hat %2 Kanal/Kanäle.",
    "The raster has no cells.": "Das Raster hat keine Zellen.",
    "The raster is in a geographic CRS (%1): its cell sizes are degrees, not metres like its "
    "heights. Reproject it to a metric CRS first, for example with Raster > Projections > Warp "
    "(Reproject) to the UTM zone of the area.":
        "Das Raster liegt in einem geographischen KBS (%1): seine Zellgrößen sind Grad, nicht "
        "Meter wie seine Höhen. Projizieren Sie es zuerst in ein metrisches KBS, zum Beispiel mit "
        "Raster > Projektionen > Transformieren (Reprojizieren) in die UTM-Zone des Gebiets.",
    "The raster has no CRS: cell sizes are taken as metres and the outputs have no CRS.":
        "Das Raster hat kein KBS: Zellgrößen werden als Meter angenommen, die Ausgaben haben kein "
        "KBS.",
    "Mercator projection: map units are not ground metres here; cell sizes are scaled by "
    "cos(latitude of the centre) = %L1.":
        "Mercator-Projektion: Karteneinheiten sind hier keine Meter im Gelände; die Zellgrößen "
        "werden mit cos(Breite der Mitte) = %L1 skaliert.",
    "The CRS's unit is %1, not the metre: the heights must be in %1 too, and depths and lengths "
    "come out in %1.":
        "Die Einheit des KBS ist %1, nicht der Meter: die Höhen müssen ebenfalls in %1 sein, und "
        "Tiefen und Längen werden in %1 ausgegeben.",
    "Some heights are %1, a common fill value: if those cells have no data, set it as the "
    "layer's no data value (Layer Properties > Transparency) or in the file.":
        "Einige Höhen betragen %1, ein üblicher Füllwert: wenn diese Zellen keine Daten "
        "haben, setzen Sie ihn als NoData-Wert des Layers (Layereigenschaften > Transparenz) "
        "oder in der Datei.",
    "Some heights are %1, a fill value (of magnitude 1e30 or more, as float's) that no terrain "
    "has: those cells are taken as no data.":
        "Einige Höhen betragen %1, ein Füllwert (vom Betrag 1e30 oder mehr, wie der für "
        "Gleitkommazahlen), den kein Gelände hat: diese Zellen werden als NoData behandelt.",
    "The raster has %1 bands; band %2 is used.": "Das Raster hat %1 Kanäle; Kanal %2 wird verwendet.",
    "Could not write %1 whole: %2": "%1 konnte nicht vollständig geschrieben werden: %2",
    "Could not write %1 whole: the file ends cut short. Is the disk full?":
        "%1 konnte nicht vollständig geschrieben werden: die Datei bricht vorzeitig ab. Ist der "
        "Datenträger voll?",
    "Heights span %1 over a raster %2 across, more than any terrain: if they are millimetres or "
    "centimetres, give the band a scale in the file (gdal_edit.py -scale 0.001).":
        "Die Höhen umfassen %1 auf einem Raster von %2 Breite, mehr als jedes Gelände: wenn es "
        "Millimeter oder Zentimeter sind, geben Sie dem Kanal in der Datei einen Maßstab "
        "(gdal_edit.py -scale 0.001).",
    "The raster is rotated: QGIS turns it north-up, and the cells it adds around it are left out "
    "as no data.":
        "Das Raster ist gedreht: QGIS richtet es nach Norden aus, und die Zellen, die es dabei "
        "rundum hinzufügt, bleiben als NoData außen vor.",
    "Could not open the raster's data provider.":
        "Der Datenanbieter des Rasters konnte nicht geöffnet werden.",
    "Not enough memory for a %1 x %2 raster.": "Nicht genug Speicher für ein Raster von %1 x %2.",
    "Cancelled.": "Abgebrochen.",
    "Could not read rows %1 to %2 of the raster.":
        "Die Zeilen %1 bis %2 des Rasters konnten nicht gelesen werden.",
    "Silhouettes (factual and formulated)": "Silhouetten (faktisch und formuliert)",
    "silhouette,occluding contour,sketch,oblique,panorama,block diagram,plan oblique,terrain,dem,"
    "hidden":
        "Silhouette,Verdeckungskontur,Skizze,Schrägansicht,Panorama,Blockbild,Plan oblique,"
        "Gelände,DGM,verdeckt",
    "Draws the silhouette lines of a DEM seen obliquely from above as vector strokes.":
        "Zeichnet die Silhouettenlinien eines schräg von oben gesehenen DGM als Vektorstriche.",
    "Finds the lines a cartographer sketches first when drawing terrain seen obliquely from "
    "above.\n\nFactual Silhouettes are occluding contours: cells beyond which the terrain hides "
    "what lies behind it, in a parallel view with vertical exaggeration and a base slope added "
    "along the line of sight. Formulated Silhouettes are back-facing slopes that the raised view "
    "brings into sight (the candidate set), kept where the slope filter finds them significant "
    "(outside the weak/weak corner of column slope against row slope), thinned to the cell "
    "furthest from the viewer and chained across profiles.\n\nThe DEM's heights must be in "
    "metres and its CRS projected in metres; a geographic DEM is refused. Any view azimuth "
    "works; the four cardinal ones are exact.\n\nTwo line outputs: Factual silhouettes (styled "
    "bold black, width "
    "by hidden depth) and Formulated silhouettes (thinner sepia, width by slope). Separate layers "
    "so each can be styled, filtered or switched off on its own, and routed separately in models. "
    "Each stroke carries: class, cells, length, mean_slope and mean_row_slope (%), mean_depth and "
    "max_depth (m, factual only), mean_dist (ground distance from the front edge of the view, in "
    "the CRS's unit) and mean_z (m).\n\n"
    "The strokes are drawn by default, as a cartographer would publish them: joined where they "
    "continue each other, smoothed within a cell of the exact chain, and stored as LineString M "
    "whose M values weigh each point (thin at the ends, thinner at the back of the view); the "
    "styles draw those weights. The advanced parameter Strokes gives the thesis's exact strokes "
    "instead.\n\nThe stage figures (log and outputs), in percent of the "
    "cells with data: HIDDEN_PCT (cells hidden behind nearer terrain), OCCLUDING_PCT (occluding "
    "cells), CSET_PCT (the candidate set: back-facing cells the raised view brings into sight), "
    "FSET_PCT (the filtered set: visible candidates the slope filter keeps), TSET_PCT (the thinned "
    "set: one cell per filtered zone) and GSET_PCT (the generalised set: cells of the strokes "
    "kept, those with at least the minimum number of cells); FACTUAL_STROKES and "
    "FORMULATED_STROKES count the strokes.\n\n"
    "Reference: Beyond Factual to Formulated Silhouettes, PhD thesis, Department of Computer "
    "Science, University of Hull (chapters 4 and 5), extending the occluding contours of "
    "Visvalingam and Whelan (1998).":
        "Findet die Linien, die ein Kartograf zuerst skizziert, wenn er Gelände schräg von oben "
        "zeichnet.\n\nFaktische Silhouetten sind Verdeckungskonturen: Zellen, hinter denen das "
        "Gelände verbirgt, was dahinter liegt, in einer Parallelansicht mit Überhöhung und einer "
        "entlang der Blickrichtung addierten Grundneigung. Formulierte Silhouetten sind "
        "abgewandte Hänge, die der erhöhte Blick sichtbar macht (die Kandidatenmenge); sie bleiben "
        "erhalten, wo der Neigungsfilter sie für bedeutsam hält (außerhalb der schwach/schwach-"
        "Ecke von Spalten- gegen Zeilenneigung), werden auf die vom Betrachter entfernteste Zelle "
        "ausgedünnt und über die Profile verkettet.\n\nDie Höhen des DGM müssen in Metern "
        "vorliegen und sein KBS in Metern projiziert sein; ein geographisches DGM wird "
        "abgelehnt. Jede Blickrichtung ist möglich; die vier Haupthimmelsrichtungen sind "
        "exakt.\n\nZwei "
        "Linienausgaben: Faktische Silhouetten (fett schwarz, Breite nach verdeckter Tiefe) und "
        "Formulierte Silhouetten (dünner sepia, Breite nach Neigung). Getrennte Layer, damit jeder "
        "für sich gestaltet, gefiltert oder ausgeblendet und in Modellen getrennt weitergeleitet "
        "werden kann. Jeder Strich trägt: class, cells, length, mean_slope und mean_row_slope (%), "
        "mean_depth und max_depth (m, nur faktisch), mean_dist (Abstand im Gelände vom vorderen "
        "Bildrand, in der Einheit des KBS) und mean_z (m).\n\n"
        "Die Striche werden standardmäßig gezeichnet, wie sie ein Kartograf veröffentlichen "
        "würde: verbunden, wo sie einander fortsetzen, innerhalb einer Zelle der exakten Kette "
        "geglättet und als LineString M gespeichert, deren M-Werte jeden Punkt gewichten (dünn an "
        "den Enden, dünner zum hinteren Rand der Ansicht); die Stile zeichnen diese Gewichte. Der "
        "erweiterte Parameter Striche liefert stattdessen die exakten Striche der Dissertation."
        "\n\nDie Stufenkennzahlen (Protokoll und "
        "Ausgaben), in Prozent der Zellen mit Daten: HIDDEN_PCT (hinter näherem Gelände "
        "verdeckte Zellen), OCCLUDING_PCT (verdeckende Zellen), CSET_PCT (die Kandidatenmenge: "
        "abgewandte Zellen, die der erhöhte Blick sichtbar macht), FSET_PCT (die gefilterte "
        "Menge: sichtbare Kandidaten, die der Neigungsfilter behält), TSET_PCT (die ausgedünnte "
        "Menge: eine Zelle je gefilterter Zone) und GSET_PCT (die generalisierte Menge: Zellen der "
        "behaltenen Striche, die mindestens die Mindestzahl an Zellen haben); FACTUAL_STROKES und "
        "FORMULATED_STROKES zählen die Striche.\n\nQuelle: Beyond Factual to Formulated Silhouettes, Dissertation, "
        "Department of Computer Science, University of Hull (Kapitel 4 und 5), als Erweiterung der "
        "Verdeckungskonturen von Visvalingam und Whelan (1998).",
    "Elevation (DEM)": "Höhenmodell (DGM)",
    "Digital elevation model with heights in metres, in a projected CRS in metres.":
        "Digitales Geländemodell mit Höhen in Metern, in einem in Metern projizierten KBS.",
    "Band": "Kanal",
    "The band holding the heights (the first when none is chosen).":
        "Der Kanal mit den Höhen (der erste, wenn keiner gewählt ist).",
    "Waiting for another run writing %1.": "Warte auf einen anderen Lauf, der %1 schreibt.",
    "Could not read band %1 of the raster to drape.":
        "Kanal %1 des zu drapierenden Rasters konnte nicht gelesen werden.",
    "Processing the DEM in %1 strips of %2 profiles.":
        "Das DGM wird in %1 Streifen zu je %2 Profilen verarbeitet.",
    "View azimuth (degrees)": "Blickrichtung (Grad)",
    "Compass bearing the viewer faces, clockwise from grid north: 0 (from the south), 90 (from "
    "the west, the default), 180 (from the north), 270 (from the east). These four are exact; "
    "any other azimuth resamples the DEM bilinearly onto a grid aligned with the line of sight, "
    "and the strokes are mapped back exactly into the DEM's CRS.":
        "Richtung, in die der Betrachter blickt, im Uhrzeigersinn von Gitternord: 0 (von Süden), "
        "90 (von Westen, Vorgabe), 180 (von Norden), 270 (von Osten). Diese vier sind exakt; "
        "jede andere Richtung tastet das DGM bilinear auf ein an der Blickrichtung ausgerichtetes "
        "Gitter um, und die Striche werden exakt in das KBS des DGM zurückgeführt.",
    "Vertical exaggeration": "Überhöhung",
    "Factor applied to heights before occlusion is computed.":
        "Faktor, mit dem die Höhen vor der Verdeckungsberechnung multipliziert werden.",
    "Base slope (%)": "Grundneigung (%)",
    "Slope added along the line of sight, in percent: the view elevation angle is atan(base "
    "slope) above the exaggerated terrain (40 % = 21.8 degrees).":
        "Entlang der Blickrichtung addierte Neigung in Prozent: der Blickwinkel über dem "
        "überhöhten Gelände ist atan(Grundneigung) (40 % = 21,8 Grad).",
    "Row slope cut-off (%)": "Grenzwert Zeilenneigung (%)",
    "Slope filter: row (across the view) slope below which weak candidates are removed; 20 % is "
    "Macgregor's critical slope.":
        "Neigungsfilter: Neigung quer zur Blickrichtung, unter der schwache Kandidaten entfernt "
        "werden; 20 % ist Macgregors kritische Neigung.",
    "Column slope cut-off (%)": "Grenzwert Spaltenneigung (%)",
    "Slope filter: column (along the view) slope below which weak candidates are removed.":
        "Neigungsfilter: Neigung entlang der Blickrichtung, unter der schwache Kandidaten entfernt "
        "werden.",
    "Control point column slope (%)": "Spaltenneigung des Kontrollpunkts (%)",
    "Slope filter: column slope of the control point joining the two cut-offs, on the "
    "perpendicular through the origin. Smaller values keep more diagonal features; it must be "
    "below the column cut-off.":
        "Neigungsfilter: Spaltenneigung des Kontrollpunkts, der die beiden Grenzwerte verbindet, "
        "auf der Senkrechten durch den Ursprung. Kleinere Werte erhalten mehr diagonale Formen; "
        "der Wert muss unter dem Grenzwert der Spaltenneigung liegen.",
    "Adapted to the DEM": "An das DGM angepasst",
    "Fixed (the thesis's cut-offs)": "Fest (die Schwellen der Dissertation)",
    "Adapted to the DEM (the default): the cut-offs below are scaled by the DEM's median slope "
    "over 24 %, that of the terrain the thesis tuned them on at 75 m cells (from 1/16 to 4 "
    "times), so that coarse, fine, flat and steep DEMs all give a balanced sketch; height steps "
    "within half the DEM's height unit count as flat, so the sketch holds still as the view "
    "turns. Fixed: the cut-offs as given, the thesis's filter.":
        "An das DGM angepasst (Standard): die Schwellen unten werden mit der mittleren "
        "Hangneigung (Median) des DGM geteilt durch 24 % skaliert, der des Geländes, auf das die "
        "Dissertation sie bei 75-m-Zellen abgestimmt hat (1/16- bis 4-fach), so dass grobe, "
        "feine, flache und steile DGM alle eine ausgewogene Skizze ergeben; Höhenstufen "
        "innerhalb der halben Höheneinheit des DGM gelten als flach, so dass die Skizze stehen "
        "bleibt, wenn sich die Blickrichtung dreht. Fest: die Schwellen wie angegeben, der "
        "Filter der Dissertation.",
    "Adapt the filter to": "Filter anpassen an",
    "The whole DEM": "Das ganze DGM",
    "Each neighbourhood": "Jede Nachbarschaft",
    "With the adapted filter: one scale for the whole DEM, or a scale for each neighbourhood, "
    "so that a plain beside mountains keeps its subtle breaks of slope (this reads the DEM once "
    "more).":
        "Beim angepassten Filter: ein Maßstab für das ganze DGM oder einer für jede "
        "Nachbarschaft, so dass eine Ebene neben Bergen ihre feinen Gefällsknicke behält (dazu "
        "wird das DGM ein weiteres Mal gelesen).",
    "Neighbourhood (cells)": "Nachbarschaft (Zellen)",
    "With a scale for each neighbourhood: the side of a neighbourhood, in DEM cells. Scales are "
    "blended between neighbourhoods, so the filter has no seams.":
        "Bei einem Maßstab je Nachbarschaft: die Seitenlänge einer Nachbarschaft in DGM-Zellen. "
        "Zwischen Nachbarschaften werden die Maßstäbe überblendet, so dass der Filter keine "
        "Nähte hat.",
    "Slope filter adapted to the DEM: its median slope is %L1 % against %L2 % on the thesis's "
    "terrain, so the cut-offs are scaled by %L3: row %L4 %, column %L5 %, control point %L6 %.":
        "Neigungsfilter an das DGM angepasst: seine mittlere Hangneigung ist %L1 % gegenüber "
        "%L2 % im Gelände der Dissertation, daher werden die Schwellen mit %L3 skaliert: Zeile %L4 %, "
        "Spalte %L5 %, Kontrollpunkt %L6 %.",
    "Each neighbourhood of %L1 cells scales them from %L2 to %L3 times the thesis's.":
        "Jede Nachbarschaft von %L1 Zellen skaliert sie auf das %L2- bis %L3-fache der Schwellen der "
        "Dissertation.",
    "Allow for diagonals": "Diagonalen berücksichtigen",
    "If checked the removed region is the polygon through the control point; if not, the whole "
    "rectangle below both cut-offs is removed.":
        "Wenn aktiviert, wird das Polygon durch den Kontrollpunkt entfernt; sonst das ganze "
        "Rechteck unter beiden Grenzwerten.",
    "Chaining window (cells)": "Verkettungsfenster (Zellen)",
    "Formulated strokes link cells on neighbouring profiles at most this many cells apart.":
        "Formulierte Striche verbinden Zellen benachbarter Profile, die höchstens so viele Zellen "
        "auseinander liegen.",
    "Minimum stroke cells": "Mindestzahl Zellen je Strich",
    "Strokes with fewer cells are dropped (generalisation). Drawn strokes keep shorter pieces "
    "only where they close a gap between longer ones.":
        "Striche mit weniger Zellen werden verworfen (Generalisierung). Gezeichnete Striche "
        "behalten kürzere Stücke nur, wo sie eine Lücke zwischen längeren schließen.",
    "Geometry": "Geometrie",
    "Map (cell centres)": "Karte (Zellmittelpunkte)",
    "Plan oblique (the sketch)": "Plan oblique (die Skizze)",
    "Map: strokes at the cell centres in the DEM's CRS. Plan oblique: each point moved along the "
    "view azimuth by (exaggeration / base slope) x (height - lowest height), so the strokes draw "
    "the oblique sketch in the same CRS.":
        "Karte: Striche durch die Zellmittelpunkte im KBS des DGM. Plan oblique: jeder Punkt wird "
        "entlang der Blickrichtung um (Überhöhung / Grundneigung) x (Höhe - niedrigste Höhe) "
        "verschoben, sodass die Striche die Schrägskizze im selben KBS zeichnen.",
    "Formulated stroke placement": "Lage der formulierten Striche",
    "Far end of each zone": "Hinteres Ende jeder Zone",
    "Near and far ends": "Vorderes und hinteres Ende",
    "Which cells of a filtered zone become formulated silhouette points.":
        "Welche Zellen einer gefilterten Zone zu Punkten formulierter Silhouetten werden.",
    "Sub-cell occluding points": "Verdeckungspunkte zwischen Zellen",
    "Place factual points where the transformed profile peaks between cells instead of at cell "
    "centres (removes the thesis's halo).":
        "Faktische Punkte dort setzen, wo das transformierte Profil zwischen den Zellen seinen "
        "Gipfel hat, statt in die Zellmitte (beseitigt den Halo der Dissertation).",
    "Factual silhouettes": "Faktische Silhouetten",
    "Occluding contours as line strokes.": "Verdeckungskonturen als Linienstriche.",
    "Formulated silhouettes": "Formulierte Silhouetten",
    "Formulated silhouettes as line strokes.": "Formulierte Silhouetten als Linienstriche.",
    "Not enough memory for this raster.": "Nicht genug Speicher für dieses Raster.",
    "Terrain sketch": "Geländeskizze",
    "Silhouette stages (classification raster)": "Silhouetten-Stufen (Klassifikationsraster)",
    "Shows what the silhouette method does to every cell of the DEM, on the DEM's own grid: 1 "
    "visible, 2 hidden, 3 occluding (Factual Silhouette), 4 c-set (back-facing slope brought into "
    "view), 5 f-set (kept by the slope filter), 6 t-set (kept by thinning); 0 is nodata. Styled "
    "like the thesis's map views: occlusion red, hidden zones blue, c-set light grey, f-set dark "
    "grey. The stage statistics are in the results and the log.":
        "Zeigt, was das Silhouettenverfahren mit jeder Zelle des DGM macht, auf dem eigenen Gitter "
        "des DGM: 1 sichtbar, 2 verdeckt, 3 verdeckend (faktische Silhouette), 4 c-Menge "
        "(abgewandter Hang, der sichtbar wird), 5 f-Menge (vom Neigungsfilter behalten), 6 "
        "t-Menge (von der Ausdünnung behalten); 0 ist NoData. Gestaltet wie die Kartenansichten "
        "der Dissertation: Verdeckung rot, verdeckte Zonen blau, c-Menge hellgrau, f-Menge "
        "dunkelgrau. Die Stufenstatistik steht in den Ergebnissen und im Protokoll.",
    "Silhouette stages": "Silhouetten-Stufen",
    "Byte raster of stage classes on the DEM's grid.":
        "Byte-Raster der Stufenklassen auf dem Gitter des DGM.",
    "Profile plot (ridgelines)": "Profildarstellung (Kammlinien)",
    "Draws every n-th cross-section across the line of sight as it appears in the oblique view: "
    "in plan-oblique geometry (each point moved along the view azimuth by exaggeration / base "
    "slope x (height - lowest height)), with the parts hidden behind nearer terrain removed. The "
    "classic ridgeline sketch; it overlays the plan-oblique silhouettes exactly. Each line carries "
    "its cross-section number and its distance from the front of the view.":
        "Zeichnet jeden n-ten Querschnitt quer zur Blickrichtung so, wie er in der Schrägansicht "
        "erscheint: in Plan-oblique-Geometrie (jeder Punkt entlang der Blickrichtung um Überhöhung "
        "/ Grundneigung x (Höhe - niedrigste Höhe) verschoben), ohne die hinter näherem Gelände "
        "verdeckten Teile. Die klassische Kammlinienskizze; sie deckt sich genau mit den "
        "Plan-oblique-Silhouetten. Jede Linie trägt die Nummer ihres Querschnitts und ihren "
        "Abstand vom vorderen Bildrand.",
    "Every n-th cross-section": "Jeder n-te Querschnitt",
    "Distance between drawn cross-sections, in cells along the line of sight.":
        "Abstand der gezeichneten Querschnitte in Zellen entlang der Blickrichtung.",
    "Profile plot": "Profildarstellung",
    "Visible pieces of the cross-sections as lines.": "Sichtbare Teile der Querschnitte als Linien.",
    "Row slope map": "Karte der Zeilenneigung",
    "The magnitude of the slope across the line of sight, in percent, on the DEM's grid (central "
    "differences across the view). Styled light where the terrain is flat across the view and "
    "dark where it is steep, the backdrop the thesis uses under its silhouettes. Only the azimuth "
    "matters.":
        "Der Betrag der Neigung quer zur Blickrichtung in Prozent auf dem Gitter des DGM "
        "(zentrale Differenzen quer zur Ansicht). Hell, wo das Gelände quer zur Ansicht flach "
        "ist, dunkel, wo es steil ist: der Hintergrund, den die Dissertation unter ihre "
        "Silhouetten legt. Nur die Blickrichtung zählt.",
    "Row slope": "Zeilenneigung",
    "Slope filter diagram": "Diagramm des Neigungsfilters",
    "Plots, for every cell, the magnitude of its column slope (along the view) against its row "
    "slope (across the view): all cells grey, the candidate set red, the cells the slope filter "
    "keeps black, over the filter's removal region in grey with the control point circled. Run it "
    "with different filter parameters to see what they keep before drawing the silhouettes. The "
    "page opens in the Results Viewer.":
        "Trägt für jede Zelle den Betrag ihrer Spaltenneigung (entlang der Blickrichtung) gegen "
        "ihre Zeilenneigung (quer dazu) auf: alle Zellen grau, die Kandidatenmenge rot, die vom "
        "Neigungsfilter behaltenen Zellen schwarz, über dem grauen Entfernungsbereich des Filters "
        "mit eingekreistem Kontrollpunkt. Mit verschiedenen Filterparametern ausführen, um vor dem "
        "Zeichnen der Silhouetten zu sehen, was sie behalten. Die Seite öffnet sich im "
        "Ergebnisanzeiger.",
    "HTML files (*.html)": "HTML-Dateien (*.html)",
    "HTML page with the diagram as SVG.": "HTML-Seite mit dem Diagramm als SVG.",
    "Slope filter": "Neigungsfilter",
    "Drape raster (plan oblique)": "Raster drapieren (Plan oblique)",
    "Projects a raster on the DEM's grid (a hillshade, a slope or row slope map, an image; every "
    "band) into plan-oblique space: each visible cell moves along the view azimuth by "
    "exaggeration / base slope x (height - lowest height), terrain hidden behind nearer terrain "
    "is removed and slopes facing the viewer are stretched. The result lies exactly under the "
    "plan-oblique silhouettes and the profile plot made with the same view. The raster to drape "
    "must have the DEM's size (resample it to the DEM's grid first).":
        "Projiziert ein Raster auf dem Gitter des DGM (eine Schummerung, eine Neigungs- oder "
        "Zeilenneigungskarte, ein Bild; alle Kanäle) in den Plan-oblique-Raum: jede sichtbare "
        "Zelle wird entlang der Blickrichtung um Überhöhung / Grundneigung x (Höhe - niedrigste "
        "Höhe) verschoben, hinter näherem Gelände verdecktes Gelände wird entfernt und dem "
        "Betrachter zugewandte Hänge werden gedehnt. Das Ergebnis liegt genau unter den "
        "Plan-oblique-Silhouetten und der Profildarstellung derselben Ansicht. Das Raster muss "
        "die Größe des DGM haben (zuerst auf das Gitter des DGM umtasten).",
    "Raster to drape": "Zu drapierendes Raster",
    "P-stroke sketch": "P-Strich-Skizze",
    "Short strokes drawn across the line of sight where the terrain bends (Visvalingam and Dowson "
    "1998). Every profile along the view (column) and across it (row) is scored with "
    "Visvalingam's effective-area line generalisation; a visible cell whose convex or concave "
    "score reaches its class's tolerance seeds a stroke along the cross-section. Tolerances are "
    "effective areas in square metres of the triangles formed by distance (m) and unexaggerated "
    "height (m) along the profiles; the defaults are the thesis's sparse sketch of a 50 m DEM. "
    "Combined with the silhouettes: no P-stroke is seeded in an f-set cell and none is extended "
    "into one.":
        "Kurze Striche quer zur Blickrichtung, wo das Gelände knickt (Visvalingam und Dowson "
        "1998). Jedes Profil entlang der Ansicht (Spalte) und quer dazu (Zeile) wird mit "
        "Visvalingams Linienvereinfachung nach effektiver Fläche bewertet; eine sichtbare Zelle, "
        "deren konvexe oder konkave Bewertung die Toleranz ihrer Klasse erreicht, setzt einen "
        "Strich entlang des Querschnitts. Die Toleranzen sind effektive Flächen in "
        "Quadratmetern der Dreiecke aus Abstand (m) und nicht überhöhter Höhe (m) entlang der "
        "Profile; die Vorgaben sind die der spärlichen Skizze eines 50-m-DGM in der "
        "Dissertation. Zusammen mit den Silhouetten: kein P-Strich beginnt in einer Zelle der "
        "f-Menge, und keiner wird in eine hinein verlängert.",
    "Convex column tolerance (m²)": "Toleranz konvex entlang (m²)",
    "Effective area a convex bend along the view must reach.":
        "Effektive Fläche, die ein konvexer Knick entlang der Ansicht erreichen muss.",
    "Concave column tolerance (m²)": "Toleranz konkav entlang (m²)",
    "Effective area a concave bend along the view must reach.":
        "Effektive Fläche, die ein konkaver Knick entlang der Ansicht erreichen muss.",
    "Convex row tolerance (m²)": "Toleranz konvex quer (m²)",
    "Effective area a convex bend across the view must reach.":
        "Effektive Fläche, die ein konvexer Knick quer zur Ansicht erreichen muss.",
    "Concave row tolerance (m²)": "Toleranz konkav quer (m²)",
    "Effective area a concave bend across the view must reach.":
        "Effektive Fläche, die ein konkaver Knick quer zur Ansicht erreichen muss.",
    "Stroke half length (cells)": "Halbe Strichlänge (Zellen)",
    "Cells drawn on each side of a seed along the cross-section.":
        "Zellen, die auf jeder Seite eines Startpunkts entlang des Querschnitts gezeichnet werden.",
    "P-strokes": "P-Striche",
    "Profiles per strip (0: automatic)": "Profile je Streifen (0: automatisch)",
    "The DEM is read and processed this many profiles at a time, the next strip read while "
    "this one is processed, so DEMs larger than memory run too. 0 chooses 1024, more for "
    "profiles under 1024 cells (a million cells a strip), fewer for profiles over 4096 cells "
    "(four million cells a strip, at least 256), or fewer "
    "when profiles are so long that the strips would take more than 512 MB. Strips that would "
    "take more than half of this machine's memory are refused.":
        "Das DGM wird so viele Profile auf einmal gelesen und verarbeitet, der nächste Streifen "
        "wird gelesen, während dieser verarbeitet wird; so laufen auch DGM, die größer als der "
        "Speicher sind. 0 wählt 1024, mehr für Profile unter 1024 Zellen (eine Million Zellen "
        "je Streifen), weniger für Profile über 4096 Zellen (vier "
        "Millionen Zellen je Streifen, mindestens 256), oder weniger, wenn die Profile "
        "so lang sind, dass die Streifen mehr als 512 MB belegen würden. Streifen, die mehr als die Hälfte des Arbeitsspeichers dieses "
        "Rechners belegen würden, werden abgelehnt.",
    "The raster (%1 x %2 cells) is too large for this algorithm, which holds the whole DEM turned "
    "to the view: that would take more than half of this machine's memory. The Silhouettes "
    "algorithm reads large DEMs strip by strip; or clip or resample the DEM.":
        "Das Raster (%1 x %2 Zellen) ist zu groß für diesen Algorithmus, der das ganze DGM zur "
        "Blickrichtung gedreht im Speicher hält: das würde mehr als die Hälfte des "
        "Arbeitsspeichers dieses Rechners belegen. Der Algorithmus Silhouetten liest große DGM "
        "Streifen für Streifen; oder schneiden Sie das DGM zu oder verringern Sie seine Auflösung.",
    "%1 would be written into %2, the file of %3, which this algorithm reads; choose another "
    "file.":
        "%1 würde in %2 geschrieben, die Datei von %3, die dieser Algorithmus liest; wählen Sie "
        "eine andere Datei.",
    "%1 and %2 would both be written to %3, one over the other; choose different files, or "
    "save both to one GeoPackage with a layer name each.":
        "%1 und %2 würden beide nach %3 geschrieben, eines über das andere; wählen Sie "
        "verschiedene Dateien, oder speichern Sie beide in ein GeoPackage mit je einem "
        "Layernamen.",
    "P-strokes as lines with their class and score.":
        "P-Striche als Linien mit ihrer Klasse und Bewertung.",
    "A raster with the DEM's number of rows and columns; all its bands are draped.":
        "Ein Raster mit der Zeilen- und Spaltenzahl des DGM; alle seine Kanäle werden drapiert.",
    "Draped raster": "Drapiertes Raster",
    "Float32 raster in plan-oblique space, one band per source band.":
        "Float32-Raster im Plan-oblique-Raum, ein Kanal je Quellkanal.",
    "The raster to drape has %1 x %2 cells, the DEM %3 x %4: resample it to the DEM's grid first "
    "(Raster > Projections > Warp with the DEM's extent and resolution).":
        "Das zu drapierende Raster hat %1 x %2 Zellen, das DGM %3 x %4: tasten Sie es zuerst auf "
        "das Gitter des DGM um (Raster > Projektionen > Transformieren mit Ausdehnung und "
        "Auflösung des DGM).",
    "Float32 raster of |row slope| in percent.": "Float32-Raster der |Zeilenneigung| in Prozent.",
    "Terrain sketch: factual and formulated silhouettes":
        "Geländeskizze: faktische und formulierte Silhouetten",
    'Strokes':
        'Striche',
    'Drawn (joined, smoothed, tapered)':
        'Gezeichnet (verbunden, geglättet, verjüngt)',
    "Exact (the thesis's, a point per cell)":
        'Exakt (wie in der Dissertation, ein Punkt je Zelle)',
    "Drawn (the default): strokes a cartographer would publish. Pieces of one class that continue each other across a small gap are joined before short strokes are dropped; points lie between cells where the profile peaks or the slope breaks, and are smoothed along the stroke; every point carries a weight (its M value) that tapers the ends and thins the strokes towards the back of the view, which the layers' styles draw. Exact: the thesis's strokes, a point at each cell centre.":
        'Gezeichnet (Voreinstellung): Striche, wie sie ein Kartograf veröffentlichen würde. Stücke einer Klasse, die einander über eine kleine Lücke fortsetzen, werden verbunden, bevor kurze Striche entfallen; Punkte liegen zwischen den Zellen, wo das Profil gipfelt oder die Neigung bricht, und werden entlang des Strichs geglättet; jeder Punkt trägt ein Gewicht (seinen M-Wert), das die Enden verjüngt und die Striche zum hinteren Rand der Ansicht hin dünner macht, wie es die Stile der Layer zeichnen. Exakt: die Striche der Dissertation, ein Punkt in jeder Zellmitte.',
    'Join gap (cells)':
        'Verbindungslücke (Zellen)',
    'Drawn strokes: ends of two strokes this close (in cells) are joined when their directions agree. 0 joins none.':
        'Gezeichnete Striche: Enden zweier Striche, die so nahe beieinander liegen (in Zellen), werden verbunden, wenn ihre Richtungen übereinstimmen. 0 verbindet keine.',
    'Join angle (degrees)':
        'Verbindungswinkel (Grad)',
    "Drawn strokes: the largest turn between two ends' directions, and the step between them, for them to be joined.":
        'Gezeichnete Striche: die größte Drehung zwischen den Richtungen zweier Enden und dem Schritt zwischen ihnen, bei der sie noch verbunden werden.',
    'Smoothing (cells)':
        'Glättung (Zellen)',
    'Drawn strokes: the width (sigma, in cells) of the Gaussian smoothing along each stroke. 0 keeps the points where they are.':
        'Gezeichnete Striche: die Breite (Sigma, in Zellen) der Gaußschen Glättung entlang jedes Strichs. 0 lässt die Punkte, wo sie sind.',
    'Smoothing tolerance (cells)':
        'Glättungstoleranz (Zellen)',
    'Drawn strokes: no point moves farther than this (in cells) from its place on the exact chain, so smoothing never invents terrain.':
        'Gezeichnete Striche: kein Punkt liegt weiter als dies (in Zellen) von seinem Platz auf der exakten Kette, so dass die Glättung nie Gelände erfindet.',
    'Taper (share of the stroke)':
        'Verjüngung (Anteil des Strichs)',
    "Drawn strokes: the share of a stroke's length over which each end thins.":
        'Gezeichnete Striche: der Anteil der Strichlänge, über den jedes Ende dünner wird.',
    'Depth cue':
        'Tiefenwirkung',
    'Drawn strokes: the share of the weight strokes lose from the front of the view to its back.':
        'Gezeichnete Striche: der Anteil des Gewichts, den Striche vom vorderen zum hinteren Rand der Ansicht verlieren.',
    'Over-extension (cells)':
        'Überzeichnung (Zellen)',
    'Drawn strokes: each end runs on this far (in cells) along its direction, as a hand-drawn stroke does. 0: none.':
        'Gezeichnete Striche: jedes Ende läuft so weit (in Zellen) in seiner Richtung weiter, wie es ein von Hand gezeichneter Strich tut. 0: keine.',
    'Panorama sketch':
        'Panoramaskizze',
    "The silhouettes of the terrain seen from a viewpoint, as a panorama board draws them: rays are cast from the observer all round (or over a field of view), every ray a profile of the silhouette method. Factual silhouettes are the occluding edges, the skyline and the ridges in front of it; Formulated silhouettes are back-facing slopes that the sight line, descending onto them, still reaches, kept by the slope filter. Heights are lowered by the earth's curvature, lessened by refraction. The strokes come on the map (the DEM's CRS) and in the panorama (x the azimuth, y the elevation angle, in degrees, without a CRS), far strokes drawn lighter.":
        'Die Silhouetten des Geländes von einem Standpunkt aus, wie eine Panoramatafel sie zeichnet: Vom Beobachter werden Strahlen rundum (oder über ein Blickfeld) ausgesandt, jeder Strahl ein Profil der Silhouettenmethode. Faktische Silhouetten sind die verdeckenden Kanten, der Horizont und die Grate davor; formulierte Silhouetten sind abgewandte Hänge, die die Sichtlinie, auf sie hinabfallend, noch erreicht, vom Neigungsfilter ausgewählt. Die Höhen werden um die Erdkrümmung, vermindert durch die Refraktion, abgesenkt. Die Striche entstehen auf der Karte (im KBS des DGM) und im Panorama (x das Azimut, y der Höhenwinkel, in Grad, ohne KBS); ferne Striche sind heller gezeichnet.',
    'Observer':
        'Beobachter',
    'Where the viewer stands: click it on the map. It must lie on the DEM, on a cell with data.':
        'Wo der Betrachter steht: in der Karte anklicken. Der Punkt muss auf dem DGM liegen, auf einer Zelle mit Daten.',
    'Observer height (m)':
        'Beobachterhöhe (m)',
    "The eye's height above the ground at the observer, in metres.":
        'Die Augenhöhe über dem Boden am Standpunkt, in Metern.',
    'Range (map units)':
        'Reichweite (Karteneinheiten)',
    "The farthest distance drawn, in the DEM's map units; when not given, the whole DEM.":
        'Die größte gezeichnete Entfernung in den Karteneinheiten des DGM; ohne Angabe das ganze DGM.',
    'Field of view from (degrees)':
        'Blickfeld von (Grad)',
    'The field of view turns clockwise from this azimuth (from grid north) to the next. 0 to 360, the default, is all round.':
        'Das Blickfeld dreht sich im Uhrzeigersinn von diesem Azimut (von Gitternord) zum nächsten. 0 bis 360, die Vorgabe, ist rundum.',
    'Field of view to (degrees)':
        'Blickfeld bis (Grad)',
    'The azimuth the field of view ends at; equal azimuths make an empty field.':
        'Das Azimut, bei dem das Blickfeld endet; gleiche Azimute ergeben ein leeres Blickfeld.',
    'Refraction coefficient':
        'Refraktionskoeffizient',
    'Samples per cell':
        'Abtastpunkte je Zelle',
    "Samples along each ray per DEM cell. More follow the terrain between the cells' centres, so that what is seen depends less on the DEM's grid (a DEM warped to another CRS sees the same), at the square of this times the work.":
        'Abtastpunkte entlang jedes Strahls je DGM-Zelle. Mehr davon folgen dem Gelände zwischen den Zellmitten, sodass das Gesehene weniger vom Raster des DGM abhängt (ein in ein anderes KBS transformiertes DGM sieht dasselbe), bei einem Rechenaufwand, der mit dem Quadrat dieser Zahl wächst.',
    "How much refraction lessens the earth's curvature (k): heights are lowered by (1 - k) d² / 2R at distance d. 0.13 is the usual value over land.":
        'Wie stark die Refraktion die Erdkrümmung vermindert (k): Höhen werden in der Entfernung d um (1 - k) d² / 2R abgesenkt. 0,13 ist der übliche Wert über Land.',
    'Minimum stroke length (samples)':
        'Mindestlänge der Striche (Abtastpunkte)',
    'Strokes of fewer samples are dropped; at N samples per cell, strokes of fewer than N times this.':
        'Striche mit weniger Abtastpunkten werden verworfen; bei N Abtastpunkten je Zelle Striche mit weniger als dem N-fachen davon.',
    'Formulated chaining window (samples)':
        'Suchfenster der formulierten Verkettung (Abtastpunkte)',
    'How far along the next ray a formulated chain may step.':
        'Wie weit eine formulierte Kette auf dem nächsten Strahl springen darf.',
    'Panorama strokes on the map':
        'Panoramastriche auf der Karte',
    "The strokes in the DEM's CRS, with their class, distance and azimuths.":
        'Die Striche im KBS des DGM, mit ihrer Klasse, Entfernung und ihren Azimuten.',
    'Panorama':
        'Panorama',
    'The same strokes in the panorama: x the azimuth and y the elevation angle, in degrees, without a CRS. Open it in a map of its own.':
        'Dieselben Striche im Panorama: x das Azimut und y der Höhenwinkel, in Grad, ohne KBS. In einer eigenen Karte öffnen.',
    'Visibility':
        'Sichtbarkeit',
    "Optional: a raster on the DEM's grid, 1 where the ground is seen, 0 where it is hidden, nodata out of range.":
        'Optional: ein Raster auf dem Gitter des DGM, 1 wo der Boden gesehen wird, 0 wo er verdeckt ist, NoData außerhalb der Reichweite.',
    'The observer lies outside the DEM: choose a point on it.':
        'Der Beobachter liegt außerhalb des DGM: einen Punkt darauf wählen.',
    'Peaks to label':
        'Zu beschriftende Gipfel',
    'Optional: named points, the summits of a gazetteer. Those whose top the observer sees are labelled in the panorama.':
        'Optional: benannte Punkte, die Gipfel eines Ortsverzeichnisses. Die, deren Spitze der Beobachter sieht, werden im Panorama beschriftet.',
    'Peak name field':
        'Namensfeld der Gipfel',
    'The field of the peaks holding their names.':
        'Das Feld der Gipfel, das ihre Namen enthält.',
    'Peak labels':
        'Gipfelbeschriftungen',
    'The peaks in sight as leaders in the panorama, from each top straight up to its label, with the name, distance, azimuth and elevation.':
        'Die sichtbaren Gipfel als Hinweislinien im Panorama, von jeder Spitze senkrecht hinauf zu ihrer Beschriftung, mit Name, Entfernung, Azimut und Höhenwinkel.',
    "The peaks have no field '%1' for their names.":
        'Die Gipfel haben kein Feld „%1“ für ihre Namen.',
    "Drawn (the default): a stroke is cut where its chain leaps along the rays, since a leap "
    "draws no line on the terrain. Exact: the thesis's strokes, each chain whole.":
        "Gezeichnet (Standard): ein Strich wird getrennt, wo seine Kette entlang der Strahlen "
        "springt, denn ein Sprung zeichnet keine Linie im Gelände. Exakt: die Striche der "
        "Dissertation, jede Kette ganz.",
    "The raster to drape covers %1 and the DEM %2: warp it onto the DEM's grid first "
    "(Raster > Projections > Warp with the DEM's extent and resolution).":
        "Das zu drapierende Raster deckt %1 ab, das DGM %2: transformieren Sie es zuerst auf das "
        "Raster des DGM (Raster > Projektionen > Transformieren mit Ausdehnung und Auflösung des "
        "DGM).",
    "The raster to drape is in %1, the DEM in %2: warp it onto the DEM's grid and CRS first.":
        "Das zu drapierende Raster liegt in %1, das DGM in %2: transformieren Sie es zuerst auf "
        "Raster und KBS des DGM.",
}


def main():
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "terrain_sketch_de.ts")
    tree = ET.parse(path)
    missing = []
    for message in tree.getroot().iter("message"):
        source = message.find("source").text
        translation = message.find("translation")
        if source in GERMAN:
            translation.text = GERMAN[source]
            translation.attrib.pop("type", None)
        else:
            missing.append(source)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    for source in missing:
        print("no German for:", source[:80], file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
