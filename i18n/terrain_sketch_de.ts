<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de_DE">
<context>
    <name>ClassificationAlgorithm</name>
    <message>
        <location filename="../plugin/classification_algorithm.cpp" line="20" />
        <source>Silhouette stages (classification raster)</source>
        <translation>Silhouetten-Stufen (Klassifikationsraster)</translation>
    </message>
    <message>
        <location filename="../plugin/classification_algorithm.cpp" line="24" />
        <source>Shows what the silhouette method does to every cell of the DEM, on the DEM's own grid: 1 visible, 2 hidden, 3 occluding (Factual Silhouette), 4 c-set (back-facing slope brought into view), 5 f-set (kept by the slope filter), 6 t-set (kept by thinning); 0 is nodata. Styled like the thesis's map views: occlusion red, hidden zones blue, c-set light grey, f-set dark grey. The stage statistics are in the results and the log.</source>
        <translation>Zeigt, was das Silhouettenverfahren mit jeder Zelle des DGM macht, auf dem eigenen Gitter des DGM: 1 sichtbar, 2 verdeckt, 3 verdeckend (faktische Silhouette), 4 c-Menge (abgewandter Hang, der sichtbar wird), 5 f-Menge (vom Neigungsfilter behalten), 6 t-Menge (von der Ausdünnung behalten); 0 ist NoData. Gestaltet wie die Kartenansichten der Dissertation: Verdeckung rot, verdeckte Zonen blau, c-Menge hellgrau, f-Menge dunkelgrau. Die Stufenstatistik steht in den Ergebnissen und im Protokoll.</translation>
    </message>
    <message>
        <location filename="../plugin/classification_algorithm.cpp" line="42" />
        <location filename="../plugin/classification_algorithm.cpp" line="64" />
        <source>Silhouette stages</source>
        <translation>Silhouetten-Stufen</translation>
    </message>
    <message>
        <location filename="../plugin/classification_algorithm.cpp" line="43" />
        <source>Byte raster of stage classes on the DEM's grid.</source>
        <translation>Byte-Raster der Stufenklassen auf dem Gitter des DGM.</translation>
    </message>
</context>
<context>
    <name>CoreErrors</name>
    <message>
        <location filename="../plugin/core_errors.h" line="24" />
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../plugin/core_errors.h" line="28" />
        <source>Not enough memory for this raster.</source>
        <translation>Nicht genug Speicher für dieses Raster.</translation>
    </message>
</context>
<context>
    <name>DemViewAlgorithm</name>
    <message>
        <location filename="../plugin/dem_view_algorithm.cpp" line="113" />
        <source>%1 and %2 would both be written to %3, one over the other; choose different files, or save both to one GeoPackage with a layer name each.</source>
        <translation>%1 und %2 würden beide nach %3 geschrieben, eines über das andere; wählen Sie verschiedene Dateien, oder speichern Sie beide in ein GeoPackage mit je einem Layernamen.</translation>
    </message>
    <message>
        <location filename="../plugin/dem_view_algorithm.cpp" line="108" />
        <source>%1 would be written into %2, the file of %3, which this algorithm reads; choose another file.</source>
        <translation>%1 würde in %2 geschrieben, die Datei von %3, die dieser Algorithmus liest; wählen Sie eine andere Datei.</translation>
    </message>
    <message>
        <location filename="../plugin/dem_view_algorithm.cpp" line="82" />
        <source>%1 must be a GeoTIFF (.tif): %2 is another format.</source>
        <translation>%1 muss ein GeoTIFF (.tif) sein: %2 hat ein anderes Format.</translation>
    </message>
    <message>
        <location filename="../plugin/dem_view_algorithm.cpp" line="152" />
        <source>%1, band %2</source>
        <translation>%1, Band %2</translation>
    </message>
    <message>
        <location filename="../plugin/dem_view_algorithm.cpp" line="173" />
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
</context>
<context>
    <name>DrapeAlgorithm</name>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="29" />
        <source>Drape raster (plan oblique)</source>
        <translation>Raster drapieren (Plan oblique)</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="33" />
        <source>Projects a raster on the DEM's grid (a hillshade, a slope or row slope map, an image; every band) into plan-oblique space: each visible cell moves along the view azimuth by exaggeration / base slope x (height - lowest height), terrain hidden behind nearer terrain is removed and slopes facing the viewer are stretched. The result lies exactly under the plan-oblique silhouettes and the profile plot made with the same view. The raster to drape must have the DEM's size (resample it to the DEM's grid first).</source>
        <translation>Projiziert ein Raster auf dem Gitter des DGM (eine Schummerung, eine Neigungs- oder Zeilenneigungskarte, ein Bild; alle Kanäle) in den Plan-oblique-Raum: jede sichtbare Zelle wird entlang der Blickrichtung um Überhöhung / Grundneigung x (Höhe - niedrigste Höhe) verschoben, hinter näherem Gelände verdecktes Gelände wird entfernt und dem Betrachter zugewandte Hänge werden gedehnt. Das Ergebnis liegt genau unter den Plan-oblique-Silhouetten und der Profildarstellung derselben Ansicht. Das Raster muss die Größe des DGM haben (zuerst auf das Gitter des DGM umtasten).</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="51" />
        <source>Raster to drape</source>
        <translation>Zu drapierendes Raster</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="52" />
        <source>A raster with the DEM's number of rows and columns; all its bands are draped.</source>
        <translation>Ein Raster mit der Zeilen- und Spaltenzahl des DGM; alle seine Kanäle werden drapiert.</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="54" />
        <source>Draped raster</source>
        <translation>Drapiertes Raster</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="55" />
        <source>Float32 raster in plan-oblique space, one band per source band.</source>
        <translation>Float32-Raster im Plan-oblique-Raum, ein Kanal je Quellkanal.</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="74" />
        <source>The raster to drape has %1 x %2 cells, the DEM %3 x %4: resample it to the DEM's grid first (Raster &gt; Projections &gt; Warp with the DEM's extent and resolution).</source>
        <translation>Das zu drapierende Raster hat %1 x %2 Zellen, das DGM %3 x %4: tasten Sie es zuerst auf das Gitter des DGM um (Raster &gt; Projektionen &gt; Transformieren mit Ausdehnung und Auflösung des DGM).</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="91" />
        <source>The raster to drape covers %1 and the DEM %2: warp it onto the DEM's grid first (Raster &gt; Projections &gt; Warp with the DEM's extent and resolution).</source>
        <translation>Das zu drapierende Raster deckt %1 ab, das DGM %2: transformieren Sie es zuerst auf das Raster des DGM (Raster &gt; Projektionen &gt; Transformieren mit Ausdehnung und Auflösung des DGM).</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="97" />
        <source>The raster to drape is in %1, the DEM in %2: warp it onto the DEM's grid and CRS first.</source>
        <translation>Das zu drapierende Raster liegt in %1, das DGM in %2: transformieren Sie es zuerst auf Raster und KBS des DGM.</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="127" />
        <source>Could not read band %1 of the raster to drape.</source>
        <translation>Kanal %1 des zu drapierenden Rasters konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="146" />
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../plugin/drape_algorithm.cpp" line="151" />
        <source>A drape of %1</source>
        <translation>Drapierung von %1</translation>
    </message>
</context>
<context>
    <name>FilterDiagramAlgorithm</name>
    <message>
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="20" />
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="41" />
        <source>Slope filter diagram</source>
        <translation>Diagramm des Neigungsfilters</translation>
    </message>
    <message>
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="24" />
        <source>Plots, for every cell, the magnitude of its column slope (along the view) against its row slope (across the view): all cells grey, the candidate set red, the cells the slope filter keeps black, over the filter's removal region in grey with the control point circled. Run it with different filter parameters to see what they keep before drawing the silhouettes. The page opens in the Results Viewer.</source>
        <translation>Trägt für jede Zelle den Betrag ihrer Spaltenneigung (entlang der Blickrichtung) gegen ihre Zeilenneigung (quer dazu) auf: alle Zellen grau, die Kandidatenmenge rot, die vom Neigungsfilter behaltenen Zellen schwarz, über dem grauen Entfernungsbereich des Filters mit eingekreistem Kontrollpunkt. Mit verschiedenen Filterparametern ausführen, um vor dem Zeichnen der Silhouetten zu sehen, was sie behalten. Die Seite öffnet sich im Ergebnisanzeiger.</translation>
    </message>
    <message>
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="41" />
        <source>HTML files (*.html)</source>
        <translation>HTML-Dateien (*.html)</translation>
    </message>
    <message>
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="42" />
        <source>HTML page with the diagram as SVG.</source>
        <translation>HTML-Seite mit dem Diagramm als SVG.</translation>
    </message>
    <message>
        <location filename="../plugin/filter_diagram_algorithm.cpp" line="60" />
        <source>Slope filter</source>
        <translation>Neigungsfilter</translation>
    </message>
</context>
<context>
    <name>LineOutput</name>
    <message>
        <location filename="../plugin/line_output.cpp" line="57" />
        <source>%1 keeps no M values, so the drawn strokes' weights (their taper and depth, which the styles draw) are left out; GeoPackage, FlatGeobuf, Shapefile or CSV keep them.</source>
        <translation>%1 speichert keine M-Werte, daher entfallen die Gewichte der gezeichneten Striche (ihre Verjüngung und Tiefe, die die Stile zeichnen); GeoPackage, FlatGeobuf, Shapefile oder CSV behalten sie.</translation>
    </message>
    <message>
        <location filename="../plugin/line_output.cpp" line="132" />
        <source>Internal error: no output set for %1.</source>
        <translation>Interner Fehler: keine Ausgabemenge für %1.</translation>
    </message>
    <message>
        <location filename="../plugin/line_output.cpp" line="141" />
        <source>Waiting for another run writing %1.</source>
        <translation>Warte auf einen anderen Lauf, der %1 schreibt.</translation>
    </message>
    <message>
        <location filename="../plugin/line_output.cpp" line="277" />
        <source>Could not write %1 whole: the file ends cut short. Is the disk full?</source>
        <translation>%1 konnte nicht vollständig geschrieben werden: die Datei bricht vorzeitig ab. Ist der Datenträger voll?</translation>
    </message>
    <message>
        <location filename="../plugin/line_output.cpp" line="294" />
        <source>Could not write %1 whole: %2</source>
        <translation>%1 konnte nicht vollständig geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>PStrokeAlgorithm</name>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="20" />
        <source>P-stroke sketch</source>
        <translation>P-Strich-Skizze</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="24" />
        <source>Short strokes drawn across the line of sight where the terrain bends (Visvalingam and Dowson 1998). Every profile along the view (column) and across it (row) is scored with Visvalingam's effective-area line generalisation; a visible cell whose convex or concave score reaches its class's tolerance seeds a stroke along the cross-section. Tolerances are effective areas in square metres of the triangles formed by distance (m) and unexaggerated height (m) along the profiles; the defaults are the thesis's sparse sketch of a 50 m DEM. Combined with the silhouettes: no P-stroke is seeded in an f-set cell and none is extended into one.</source>
        <translation>Kurze Striche quer zur Blickrichtung, wo das Gelände knickt (Visvalingam und Dowson 1998). Jedes Profil entlang der Ansicht (Spalte) und quer dazu (Zeile) wird mit Visvalingams Linienvereinfachung nach effektiver Fläche bewertet; eine sichtbare Zelle, deren konvexe oder konkave Bewertung die Toleranz ihrer Klasse erreicht, setzt einen Strich entlang des Querschnitts. Die Toleranzen sind effektive Flächen in Quadratmetern der Dreiecke aus Abstand (m) und nicht überhöhter Höhe (m) entlang der Profile; die Vorgaben sind die der spärlichen Skizze eines 50-m-DGM in der Dissertation. Zusammen mit den Silhouetten: kein P-Strich beginnt in einer Zelle der f-Menge, und keiner wird in eine hinein verlängert.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="47" />
        <source>Convex column tolerance (m²)</source>
        <translation>Toleranz konvex entlang (m²)</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="48" />
        <source>Effective area a convex bend along the view must reach.</source>
        <translation>Effektive Fläche, die ein konvexer Knick entlang der Ansicht erreichen muss.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="49" />
        <source>Concave column tolerance (m²)</source>
        <translation>Toleranz konkav entlang (m²)</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="50" />
        <source>Effective area a concave bend along the view must reach.</source>
        <translation>Effektive Fläche, die ein konkaver Knick entlang der Ansicht erreichen muss.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="51" />
        <source>Convex row tolerance (m²)</source>
        <translation>Toleranz konvex quer (m²)</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="52" />
        <source>Effective area a convex bend across the view must reach.</source>
        <translation>Effektive Fläche, die ein konvexer Knick quer zur Ansicht erreichen muss.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="53" />
        <source>Concave row tolerance (m²)</source>
        <translation>Toleranz konkav quer (m²)</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="54" />
        <source>Effective area a concave bend across the view must reach.</source>
        <translation>Effektive Fläche, die ein konkaver Knick quer zur Ansicht erreichen muss.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="56" />
        <source>Stroke half length (cells)</source>
        <translation>Halbe Strichlänge (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="58" />
        <source>Cells drawn on each side of a seed along the cross-section.</source>
        <translation>Zellen, die auf jeder Seite eines Startpunkts entlang des Querschnitts gezeichnet werden.</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="61" />
        <location filename="../plugin/pstroke_algorithm.cpp" line="90" />
        <source>P-strokes</source>
        <translation>P-Striche</translation>
    </message>
    <message>
        <location filename="../plugin/pstroke_algorithm.cpp" line="62" />
        <source>P-strokes as lines with their class and score.</source>
        <translation>P-Striche als Linien mit ihrer Klasse und Bewertung.</translation>
    </message>
</context>
<context>
    <name>PanoramaAlgorithm</name>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="48" />
        <source>Panorama sketch</source>
        <translation>Panoramaskizze</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="52" />
        <source>The silhouettes of the terrain seen from a viewpoint, as a panorama board draws them: rays are cast from the observer all round (or over a field of view), every ray a profile of the silhouette method. Factual silhouettes are the occluding edges, the skyline and the ridges in front of it; Formulated silhouettes are back-facing slopes that the sight line, descending onto them, still reaches, kept by the slope filter. Heights are lowered by the earth's curvature, lessened by refraction. The strokes come on the map (the DEM's CRS) and in the panorama (x the azimuth, y the elevation angle, in degrees, without a CRS), far strokes drawn lighter.</source>
        <translation>Die Silhouetten des Geländes von einem Standpunkt aus, wie eine Panoramatafel sie zeichnet: Vom Beobachter werden Strahlen rundum (oder über ein Blickfeld) ausgesandt, jeder Strahl ein Profil der Silhouettenmethode. Faktische Silhouetten sind die verdeckenden Kanten, der Horizont und die Grate davor; formulierte Silhouetten sind abgewandte Hänge, die die Sichtlinie, auf sie hinabfallend, noch erreicht, vom Neigungsfilter ausgewählt. Die Höhen werden um die Erdkrümmung, vermindert durch die Refraktion, abgesenkt. Die Striche entstehen auf der Karte (im KBS des DGM) und im Panorama (x das Azimut, y der Höhenwinkel, in Grad, ohne KBS); ferne Striche sind heller gezeichnet.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="69" />
        <source>Observer</source>
        <translation>Beobachter</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="70" />
        <source>Where the viewer stands: click it on the map. It must lie on the DEM, on a cell with data.</source>
        <translation>Wo der Betrachter steht: in der Karte anklicken. Der Punkt muss auf dem DGM liegen, auf einer Zelle mit Daten.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="72" />
        <source>Observer height (m)</source>
        <translation>Beobachterhöhe (m)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="74" />
        <source>The eye's height above the ground at the observer, in metres.</source>
        <translation>Die Augenhöhe über dem Boden am Standpunkt, in Metern.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="76" />
        <source>Range (map units)</source>
        <translation>Reichweite (Karteneinheiten)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="79" />
        <source>The farthest distance drawn, in the DEM's map units; when not given, the whole DEM.</source>
        <translation>Die größte gezeichnete Entfernung in den Karteneinheiten des DGM; ohne Angabe das ganze DGM.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="82" />
        <source>Field of view from (degrees)</source>
        <translation>Blickfeld von (Grad)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="83" />
        <source>The field of view turns clockwise from this azimuth (from grid north) to the next. 0 to 360, the default, is all round.</source>
        <translation>Das Blickfeld dreht sich im Uhrzeigersinn von diesem Azimut (von Gitternord) zum nächsten. 0 bis 360, die Vorgabe, ist rundum.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="86" />
        <source>Field of view to (degrees)</source>
        <translation>Blickfeld bis (Grad)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="87" />
        <source>The azimuth the field of view ends at; equal azimuths make an empty field.</source>
        <translation>Das Azimut, bei dem das Blickfeld endet; gleiche Azimute ergeben ein leeres Blickfeld.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="88" />
        <source>Refraction coefficient</source>
        <translation>Refraktionskoeffizient</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="90" />
        <source>How much refraction lessens the earth's curvature (k): heights are lowered by (1 - k) d² / 2R at distance d. 0.13 is the usual value over land.</source>
        <translation>Wie stark die Refraktion die Erdkrümmung vermindert (k): Höhen werden in der Entfernung d um (1 - k) d² / 2R abgesenkt. 0,13 ist der übliche Wert über Land.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="93" />
        <source>Samples per cell</source>
        <translation>Abtastpunkte je Zelle</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="95" />
        <source>Samples along each ray per DEM cell. More follow the terrain between the cells' centres, so that what is seen depends less on the DEM's grid (a DEM warped to another CRS sees the same), at the square of this times the work.</source>
        <translation>Abtastpunkte entlang jedes Strahls je DGM-Zelle. Mehr davon folgen dem Gelände zwischen den Zellmitten, sodass das Gesehene weniger vom Raster des DGM abhängt (ein in ein anderes KBS transformiertes DGM sieht dasselbe), bei einem Rechenaufwand, der mit dem Quadrat dieser Zahl wächst.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="99" />
        <source>Panorama exaggeration</source>
        <translation>Überhöhung des Panoramas</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="100" />
        <source>How many times as tall as its azimuths are wide the Panorama layer draws its elevation angles, 1 to 50. 0, the default, chooses up to 5 so that a wide field of view is no flat strip. The Panorama layout draws it so.</source>
        <translation>Wie viel Mal so hoch, wie seine Azimute breit sind, der Panorama-Layer seine Höhenwinkel zeichnet, 1 bis 50. 0, die Voreinstellung, wählt bis zu 5, damit ein weites Blickfeld kein flacher Streifen ist. Das Panorama-Layout zeichnet es so.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="110" />
        <source>Minimum stroke length (samples)</source>
        <translation>Mindestlänge der Striche (Abtastpunkte)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="112" />
        <source>Strokes of fewer samples are dropped; at N samples per cell, strokes of fewer than N times this.</source>
        <translation>Striche mit weniger Abtastpunkten werden verworfen; bei N Abtastpunkten je Zelle Striche mit weniger als dem N-fachen davon.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="115" />
        <source>Formulated chaining window (samples)</source>
        <translation>Suchfenster der formulierten Verkettung (Abtastpunkte)</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="117" />
        <source>How far along the next ray a formulated chain may step.</source>
        <translation>Wie weit eine formulierte Kette auf dem nächsten Strahl springen darf.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="119" />
        <source>Drawn (the default): a stroke is cut where its chain leaps along the rays, since a leap draws no line on the terrain. Exact: the thesis's strokes, each chain whole.</source>
        <translation>Gezeichnet (Standard): ein Strich wird getrennt, wo seine Kette entlang der Strahlen springt, denn ein Sprung zeichnet keine Linie im Gelände. Exakt: die Striche der Dissertation, jede Kette ganz.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="121" />
        <source>Panorama strokes on the map</source>
        <translation>Panoramastriche auf der Karte</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="123" />
        <source>The strokes in the DEM's CRS, with their class, distance and azimuths.</source>
        <translation>Die Striche im KBS des DGM, mit ihrer Klasse, Entfernung und ihren Azimuten.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="124" />
        <location filename="../plugin/panorama_algorithm.cpp" line="294" />
        <source>Panorama</source>
        <translation>Panorama</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="125" />
        <source>The same strokes in the panorama: x the azimuth and y the elevation angle, in degrees, without a CRS. Open it in a map of its own.</source>
        <translation>Dieselben Striche im Panorama: x das Azimut und y der Höhenwinkel, in Grad, ohne KBS. In einer eigenen Karte öffnen.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="128" />
        <source>Peaks to label</source>
        <translation>Zu beschriftende Gipfel</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="129" />
        <source>Optional: named points, the summits of a gazetteer. Those whose top the observer sees are labelled in the panorama.</source>
        <translation>Optional: benannte Punkte, die Gipfel eines Ortsverzeichnisses. Die, deren Spitze der Beobachter sieht, werden im Panorama beschriftet.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="132" />
        <source>Peak name field</source>
        <translation>Namensfeld der Gipfel</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="134" />
        <source>The field of the peaks holding their names.</source>
        <translation>Das Feld der Gipfel, das ihre Namen enthält.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="135" />
        <source>Peak labels</source>
        <translation>Gipfelbeschriftungen</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="137" />
        <source>The peaks in sight as leaders in the panorama, from each top straight up to its label, with the name, distance, azimuth and elevation.</source>
        <translation>Die sichtbaren Gipfel als Hinweislinien im Panorama, von jeder Spitze senkrecht hinauf zu ihrer Beschriftung, mit Name, Entfernung, Azimut und Höhenwinkel.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="139" />
        <source>Visibility</source>
        <translation>Sichtbarkeit</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="141" />
        <source>Optional: a raster on the DEM's grid, 1 where the ground is seen, 0 where it is hidden, nodata out of range.</source>
        <translation>Optional: ein Raster auf dem Gitter des DGM, 1 wo der Boden gesehen wird, 0 wo er verdeckt ist, NoData außerhalb der Reichweite.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="156" />
        <source>The observer lies outside the DEM: choose a point on it.</source>
        <translation>Der Beobachter liegt außerhalb des DGM: einen Punkt darauf wählen.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="220" />
        <source>The peaks have no field '%1' for their names.</source>
        <translation>Die Gipfel haben kein Feld „%1“ für ihre Namen.</translation>
    </message>
    <message>
        <location filename="../plugin/panorama_algorithm.cpp" line="282" />
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
</context>
<context>
    <name>PanoramaLayout</name>
    <message>
        <location filename="../plugin/panorama_layout.cpp" line="88" />
        <source>%1 10 mm on the page: %L2° of azimuth.</source>
        <translation>%1 10 mm auf der Seite: %L2° Azimut.</translation>
    </message>
</context>
<context>
    <name>ProfilePlotAlgorithm</name>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="19" />
        <source>Profile plot (ridgelines)</source>
        <translation>Profildarstellung (Kammlinien)</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="23" />
        <source>Draws every n-th cross-section across the line of sight as it appears in the oblique view: in plan-oblique geometry (each point moved along the view azimuth by exaggeration / base slope x (height - lowest height)), with the parts hidden behind nearer terrain removed. The classic ridgeline sketch; it overlays the plan-oblique silhouettes exactly. Each line carries its cross-section number and its distance from the front of the view.</source>
        <translation>Zeichnet jeden n-ten Querschnitt quer zur Blickrichtung so, wie er in der Schrägansicht erscheint: in Plan-oblique-Geometrie (jeder Punkt entlang der Blickrichtung um Überhöhung / Grundneigung x (Höhe - niedrigste Höhe) verschoben), ohne die hinter näherem Gelände verdeckten Teile. Die klassische Kammlinienskizze; sie deckt sich genau mit den Plan-oblique-Silhouetten. Jede Linie trägt die Nummer ihres Querschnitts und ihren Abstand vom vorderen Bildrand.</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="40" />
        <source>Every n-th cross-section</source>
        <translation>Jeder n-te Querschnitt</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="42" />
        <source>Distance between drawn cross-sections, in cells along the line of sight.</source>
        <translation>Abstand der gezeichneten Querschnitte in Zellen entlang der Blickrichtung.</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="43" />
        <source>Profile plot</source>
        <translation>Profildarstellung</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="45" />
        <source>Visible pieces of the cross-sections as lines.</source>
        <translation>Sichtbare Teile der Querschnitte als Linien.</translation>
    </message>
    <message>
        <location filename="../plugin/profile_plot_algorithm.cpp" line="77" />
        <source>Profile lines</source>
        <translation>Profillinien</translation>
    </message>
</context>
<context>
    <name>QmlStyler</name>
    <message>
        <location filename="../plugin/layer_style.cpp" line="35" />
        <source>Could not apply style %1: %2</source>
        <translation>Stil %1 konnte nicht angewendet werden: %2</translation>
    </message>
</context>
<context>
    <name>RasterGrid</name>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="125" />
        <source>The input raster layer is not valid.</source>
        <translation>Der Eingaberasterlayer ist ungültig.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="130" />
        <source>Band %1 does not exist: the raster has %2 band(s).</source>
        <translation>Kanal %1 existiert nicht: das Raster hat %2 Kanal/Kanäle.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="137" />
        <source>The raster has no cells.</source>
        <translation>Das Raster hat keine Zellen.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="162" />
        <source>Band %1 of the raster's %2 is a colour channel (red, green, blue or alpha) of an image, not heights: choose a DEM.</source>
        <translation>Band %1 der %2 Bänder des Rasters ist ein Farbkanal (Rot, Grün, Blau oder Alpha) eines Bildes, keine Höhen: wählen Sie ein DGM.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="168" />
        <source>A corner of the raster lies at a coordinate that is not a finite number: its georeferencing is wrong. Set its corners, for example with gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.</source>
        <translation>Eine Ecke des Rasters liegt bei einer Koordinate, die keine endliche Zahl ist: seine Georeferenzierung ist falsch. Setzen Sie seine Ecken, zum Beispiel mit gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="172" />
        <source>The raster's corners lie up to %L1 from the CRS's origin, too far for coordinates to tell a thousandth of its %L2 cells apart: its georeferencing is wrong. Set its corners, for example with gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.</source>
        <translation>Die Ecken des Rasters liegen bis zu %L1 vom Ursprung des KBS entfernt, zu weit, als dass Koordinaten ein Tausendstel seiner Zellen von %L2 unterscheiden könnten: seine Georeferenzierung ist falsch. Setzen Sie seine Ecken, zum Beispiel mit gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="178" />
        <source>The raster is in a geographic CRS (%1): its cell sizes are degrees, not metres like its heights. Reproject it to a metric CRS first, for example with Raster &gt; Projections &gt; Warp (Reproject) to the UTM zone of the area.</source>
        <translation>Das Raster liegt in einem geographischen KBS (%1): seine Zellgrößen sind Grad, nicht Meter wie seine Höhen. Projizieren Sie es zuerst in ein metrisches KBS, zum Beispiel mit Raster &gt; Projektionen &gt; Transformieren (Reprojizieren) in die UTM-Zone des Gebiets.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="183" />
        <source>The raster has no CRS: cell sizes are taken as metres and the outputs have no CRS.</source>
        <translation>Das Raster hat kein KBS: Zellgrößen werden als Meter angenommen, die Ausgaben haben kein KBS.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="191" />
        <source>The CRS's unit is %1, not the metre: the heights must be in %1 too, and depths and lengths come out in %1.</source>
        <translation>Die Einheit des KBS ist %1, nicht der Meter: die Höhen müssen ebenfalls in %1 sein, und Tiefen und Längen werden in %1 ausgegeben.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="195" />
        <source>The raster has %1 bands; band %2 is used.</source>
        <translation>Das Raster hat %1 Kanäle; Kanal %2 wird verwendet.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="206" />
        <source>Heights span %1 over a raster %2 across, more than any terrain: if they are millimetres or centimetres, give the band a scale in the file (gdal_edit.py -scale 0.001).</source>
        <translation>Die Höhen umfassen %1 auf einem Raster von %2 Breite, mehr als jedes Gelände: wenn es Millimeter oder Zentimeter sind, geben Sie dem Kanal in der Datei einen Maßstab (gdal_edit.py -scale 0.001).</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="149" />
        <source>The raster is rotated: QGIS turns it north-up, and the cells it adds around it are left out as no data.</source>
        <translation>Das Raster ist gedreht: QGIS richtet es nach Norden aus, und die Zellen, die es dabei rundum hinzufügt, bleiben als NoData außen vor.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="154" />
        <source>Could not open the raster's data provider.</source>
        <translation>Der Datenanbieter des Rasters konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="187" />
        <source>Mercator projection: map units are not ground metres here; cell sizes are scaled by cos(latitude of the centre) = %L1.</source>
        <translation>Mercator-Projektion: Karteneinheiten sind hier keine Meter im Gelände; die Zellgrößen werden mit cos(Breite der Mitte) = %L1 skaliert.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="197" />
        <source>Some heights are %1, a common fill value: if those cells have no data, set it as the layer's no data value (Layer Properties &gt; Transparency) or in the file.</source>
        <translation>Einige Höhen betragen %1, ein üblicher Füllwert: wenn diese Zellen keine Daten haben, setzen Sie ihn als NoData-Wert des Layers (Layereigenschaften &gt; Transparenz) oder in der Datei.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="202" />
        <source>Some heights are %1, a fill value (of magnitude 1e30 or more, as float's) that no terrain has: those cells are taken as no data.</source>
        <translation>Einige Höhen betragen %1, ein Füllwert (vom Betrag 1e30 oder mehr, wie der für Gleitkommazahlen), den kein Gelände hat: diese Zellen werden als NoData behandelt.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="337" />
        <source>The raster (%1 x %2 cells) is too large for this algorithm, which holds the whole DEM turned to the view: that would take more than half of this machine's memory. The Silhouettes algorithm reads large DEMs strip by strip; or clip or resample the DEM.</source>
        <translation>Das Raster (%1 x %2 Zellen) ist zu groß für diesen Algorithmus, der das ganze DGM zur Blickrichtung gedreht im Speicher hält: das würde mehr als die Hälfte des Arbeitsspeichers dieses Rechners belegen. Der Algorithmus Silhouetten liest große DGM Streifen für Streifen; oder schneiden Sie das DGM zu oder verringern Sie seine Auflösung.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="349" />
        <source>Not enough memory for a %1 x %2 raster.</source>
        <translation>Nicht genug Speicher für ein Raster von %1 x %2.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="358" />
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../plugin/raster_grid.cpp" line="313" />
        <source>Could not read rows %1 to %2 of the raster.</source>
        <translation>Die Zeilen %1 bis %2 des Rasters konnten nicht gelesen werden.</translation>
    </message>
</context>
<context>
    <name>RowSlopeAlgorithm</name>
    <message>
        <location filename="../plugin/row_slope_algorithm.cpp" line="17" />
        <source>Row slope map</source>
        <translation>Karte der Zeilenneigung</translation>
    </message>
    <message>
        <location filename="../plugin/row_slope_algorithm.cpp" line="21" />
        <source>The magnitude of the slope across the line of sight, in percent, on the DEM's grid (central differences across the view). Styled light where the terrain is flat across the view and dark where it is steep, the backdrop the thesis uses under its silhouettes. Only the azimuth matters.</source>
        <translation>Der Betrag der Neigung quer zur Blickrichtung in Prozent auf dem Gitter des DGM (zentrale Differenzen quer zur Ansicht). Hell, wo das Gelände quer zur Ansicht flach ist, dunkel, wo es steil ist: der Hintergrund, den die Dissertation unter ihre Silhouetten legt. Nur die Blickrichtung zählt.</translation>
    </message>
    <message>
        <location filename="../plugin/row_slope_algorithm.cpp" line="36" />
        <location filename="../plugin/row_slope_algorithm.cpp" line="52" />
        <source>Row slope</source>
        <translation>Zeilenneigung</translation>
    </message>
    <message>
        <location filename="../plugin/row_slope_algorithm.cpp" line="37" />
        <source>Float32 raster of |row slope| in percent.</source>
        <translation>Float32-Raster der |Zeilenneigung| in Prozent.</translation>
    </message>
</context>
<context>
    <name>SharedParameters</name>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="28" />
        <source>View azimuth (degrees)</source>
        <translation>Blickrichtung (Grad)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="29" />
        <source>Compass bearing the viewer faces, clockwise from grid north: 0 (from the south), 90 (from the west, the default), 180 (from the north), 270 (from the east). These four are exact; any other azimuth resamples the DEM bilinearly onto a grid aligned with the line of sight, and the strokes are mapped back exactly into the DEM's CRS.</source>
        <translation>Richtung, in die der Betrachter blickt, im Uhrzeigersinn von Gitternord: 0 (von Süden), 90 (von Westen, Vorgabe), 180 (von Norden), 270 (von Osten). Diese vier sind exakt; jede andere Richtung tastet das DGM bilinear auf ein an der Blickrichtung ausgerichtetes Gitter um, und die Striche werden exakt in das KBS des DGM zurückgeführt.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="36" />
        <source>Vertical exaggeration</source>
        <translation>Überhöhung</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="37" />
        <source>Factor applied to heights before occlusion is computed.</source>
        <translation>Faktor, mit dem die Höhen vor der Verdeckungsberechnung multipliziert werden.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="38" />
        <source>Base slope (%)</source>
        <translation>Grundneigung (%)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="40" />
        <source>Slope added along the line of sight, in percent: the view elevation angle is atan(base slope) above the exaggerated terrain (40 % = 21.8 degrees).</source>
        <translation>Entlang der Blickrichtung addierte Neigung in Prozent: der Blickwinkel über dem überhöhten Gelände ist atan(Grundneigung) (40 % = 21,8 Grad).</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="46" />
        <source>Elevation (DEM)</source>
        <translation>Höhenmodell (DGM)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="47" />
        <source>Digital elevation model with heights in metres, in a projected CRS in metres.</source>
        <translation>Digitales Geländemodell mit Höhen in Metern, in einem in Metern projizierten KBS.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="50" />
        <source>Band</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="52" />
        <source>The band holding the heights (the first when none is chosen).</source>
        <translation>Der Kanal mit den Höhen (der erste, wenn keiner gewählt ist).</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="60" />
        <source>Slope filter</source>
        <translation>Neigungsfilter</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="62" />
        <source>Adapted to the DEM</source>
        <translation>An das DGM angepasst</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="63" />
        <source>Fixed (the thesis's cut-offs)</source>
        <translation>Fest (die Schwellen der Dissertation)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="66" />
        <source>Adapted to the DEM (the default): the cut-offs below are scaled by the DEM's median slope over 24 %, that of the terrain the thesis tuned them on at 75 m cells (from 1/16 to 4 times), so that coarse, fine, flat and steep DEMs all give a balanced sketch; height steps within half the DEM's height unit count as flat, so the sketch holds still as the view turns. Fixed: the cut-offs as given, the thesis's filter.</source>
        <translation>An das DGM angepasst (Standard): die Schwellen unten werden mit der mittleren Hangneigung (Median) des DGM geteilt durch 24 % skaliert, der des Geländes, auf das die Dissertation sie bei 75-m-Zellen abgestimmt hat (1/16- bis 4-fach), so dass grobe, feine, flache und steile DGM alle eine ausgewogene Skizze ergeben; Höhenstufen innerhalb der halben Höheneinheit des DGM gelten als flach, so dass die Skizze stehen bleibt, wenn sich die Blickrichtung dreht. Fest: die Schwellen wie angegeben, der Filter der Dissertation.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="73" />
        <source>Adapt the filter to</source>
        <translation>Filter anpassen an</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="75" />
        <source>The whole DEM</source>
        <translation>Das ganze DGM</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="76" />
        <source>Each neighbourhood</source>
        <translation>Jede Nachbarschaft</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="79" />
        <source>With the adapted filter: one scale for the whole DEM, or a scale for each neighbourhood, so that a plain beside mountains keeps its subtle breaks of slope (this reads the DEM once more).</source>
        <translation>Beim angepassten Filter: ein Maßstab für das ganze DGM oder einer für jede Nachbarschaft, so dass eine Ebene neben Bergen ihre feinen Gefällsknicke behält (dazu wird das DGM ein weiteres Mal gelesen).</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="84" />
        <source>Neighbourhood (cells)</source>
        <translation>Nachbarschaft (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="88" />
        <source>With a scale for each neighbourhood: the side of a neighbourhood, in DEM cells. Scales are blended between neighbourhoods, so the filter has no seams.</source>
        <translation>Bei einem Maßstab je Nachbarschaft: die Seitenlänge einer Nachbarschaft in DGM-Zellen. Zwischen Nachbarschaften werden die Maßstäbe überblendet, so dass der Filter keine Nähte hat.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="91" />
        <source>Row slope cut-off (%)</source>
        <translation>Grenzwert Zeilenneigung (%)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="93" />
        <source>Slope filter: row (across the view) slope below which weak candidates are removed; 20 % is Macgregor's critical slope.</source>
        <translation>Neigungsfilter: Neigung quer zur Blickrichtung, unter der schwache Kandidaten entfernt werden; 20 % ist Macgregors kritische Neigung.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="96" />
        <source>Column slope cut-off (%)</source>
        <translation>Grenzwert Spaltenneigung (%)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="98" />
        <source>Slope filter: column (along the view) slope below which weak candidates are removed.</source>
        <translation>Neigungsfilter: Neigung entlang der Blickrichtung, unter der schwache Kandidaten entfernt werden.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="101" />
        <source>Control point column slope (%)</source>
        <translation>Spaltenneigung des Kontrollpunkts (%)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="103" />
        <source>Slope filter: column slope of the control point joining the two cut-offs, on the perpendicular through the origin. Smaller values keep more diagonal features; it must be below the column cut-off.</source>
        <translation>Neigungsfilter: Spaltenneigung des Kontrollpunkts, der die beiden Grenzwerte verbindet, auf der Senkrechten durch den Ursprung. Kleinere Werte erhalten mehr diagonale Formen; der Wert muss unter dem Grenzwert der Spaltenneigung liegen.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="107" />
        <source>Allow for diagonals</source>
        <translation>Diagonalen berücksichtigen</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="108" />
        <source>If checked the removed region is the polygon through the control point; if not, the whole rectangle below both cut-offs is removed.</source>
        <translation>Wenn aktiviert, wird das Polygon durch den Kontrollpunkt entfernt; sonst das ganze Rechteck unter beiden Grenzwerten.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="115" />
        <source>Strokes</source>
        <translation>Striche</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="117" />
        <source>Drawn (joined, smoothed, tapered)</source>
        <translation>Gezeichnet (verbunden, geglättet, verjüngt)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="118" />
        <source>Exact (the thesis's, a point per cell)</source>
        <translation>Exakt (wie in der Dissertation, ein Punkt je Zelle)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="133" />
        <source>Geometry</source>
        <translation>Geometrie</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="135" />
        <source>Map (cell centres)</source>
        <translation>Karte (Zellmittelpunkte)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="136" />
        <source>Plan oblique (the sketch)</source>
        <translation>Plan oblique (die Skizze)</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="139" />
        <source>Map: strokes at the cell centres in the DEM's CRS. Plan oblique: each point moved along the view azimuth by (exaggeration / base slope) x (height - lowest height), so the strokes draw the oblique sketch in the same CRS.</source>
        <translation>Karte: Striche durch die Zellmittelpunkte im KBS des DGM. Plan oblique: jeder Punkt wird entlang der Blickrichtung um (Überhöhung / Grundneigung) x (Höhe - niedrigste Höhe) verschoben, sodass die Striche die Schrägskizze im selben KBS zeichnen.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="194" />
        <source>No cell of the DEM slopes (it is flat, or too few of its cells are valid): the slope filter's cut-offs are scaled by the least, %L1: row %L2 %, column %L3 %, control point %L4 %.</source>
        <translation>Keine Zelle des DGM ist geneigt (es ist flach, oder zu wenige seiner Zellen sind gültig): die Schwellen des Neigungsfilters werden mit dem kleinsten Faktor skaliert, %L1: Zeile %L2 %, Spalte %L3 %, Kontrollpunkt %L4 %.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="203" />
        <source>Slope filter adapted to the DEM: its median slope is %L1 % against %L2 % on the thesis's terrain, so the cut-offs are scaled by %L3: row %L4 %, column %L5 %, control point %L6 %.</source>
        <translation>Neigungsfilter an das DGM angepasst: seine mittlere Hangneigung ist %L1 % gegenüber %L2 % im Gelände der Dissertation, daher werden die Schwellen mit %L3 skaliert: Zeile %L4 %, Spalte %L5 %, Kontrollpunkt %L6 %.</translation>
    </message>
    <message>
        <location filename="../plugin/shared_parameters.cpp" line="213" />
        <source>Each neighbourhood of %L1 cells scales them from %L2 to %L3 times the thesis's.</source>
        <translation>Jede Nachbarschaft von %L1 Zellen skaliert sie auf das %L2- bis %L3-fache der Schwellen der Dissertation.</translation>
    </message>
</context>
<context>
    <name>SilhouettesAlgorithm</name>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="54" />
        <source>Silhouettes (factual and formulated)</source>
        <translation>Silhouetten (faktisch und formuliert)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="58" />
        <source>silhouette,occluding contour,sketch,oblique,panorama,block diagram,plan oblique,terrain,dem,hidden</source>
        <translation>Silhouette,Verdeckungskontur,Skizze,Schrägansicht,Panorama,Blockbild,Plan oblique,Gelände,DGM,verdeckt</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="64" />
        <source>Draws the silhouette lines of a DEM seen obliquely from above as vector strokes.</source>
        <translation>Zeichnet die Silhouettenlinien eines schräg von oben gesehenen DGM als Vektorstriche.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="68" />
        <source>Finds the lines a cartographer sketches first when drawing terrain seen obliquely from above.

Factual Silhouettes are occluding contours: cells beyond which the terrain hides what lies behind it, in a parallel view with vertical exaggeration and a base slope added along the line of sight. Formulated Silhouettes are back-facing slopes that the raised view brings into sight (the candidate set), kept where the slope filter finds them significant (outside the weak/weak corner of column slope against row slope), thinned to the cell furthest from the viewer and chained across profiles.

The DEM's heights must be in metres and its CRS projected in metres; a geographic DEM is refused. Any view azimuth works; the four cardinal ones are exact.

Two line outputs: Factual silhouettes (styled bold black, width by hidden depth) and Formulated silhouettes (thinner sepia, width by slope). Separate layers so each can be styled, filtered or switched off on its own, and routed separately in models. Each stroke carries: class, cells, length, mean_slope and mean_row_slope (%), mean_depth and max_depth (m, factual only), mean_dist (ground distance from the front edge of the view, in the CRS's unit) and mean_z (m).

The strokes are drawn by default, as a cartographer would publish them: joined where they continue each other, smoothed within a cell of the exact chain, and stored as LineString M whose M values weigh each point (thin at the ends, thinner at the back of the view); the styles draw those weights. The advanced parameter Strokes gives the thesis's exact strokes instead.

The stage figures (log and outputs), in percent of the cells with data: HIDDEN_PCT (cells hidden behind nearer terrain), OCCLUDING_PCT (occluding cells), CSET_PCT (the candidate set: back-facing cells the raised view brings into sight), FSET_PCT (the filtered set: visible candidates the slope filter keeps), TSET_PCT (the thinned set: one cell per filtered zone) and GSET_PCT (the generalised set: cells of the strokes kept, those with at least the minimum number of cells); FACTUAL_STROKES and FORMULATED_STROKES count the strokes.

Reference: Beyond Factual to Formulated Silhouettes, PhD thesis, Department of Computer Science, University of Hull (chapters 4 and 5), extending the occluding contours of Visvalingam and Whelan (1998).</source>
        <translation>Findet die Linien, die ein Kartograf zuerst skizziert, wenn er Gelände schräg von oben zeichnet.

Faktische Silhouetten sind Verdeckungskonturen: Zellen, hinter denen das Gelände verbirgt, was dahinter liegt, in einer Parallelansicht mit Überhöhung und einer entlang der Blickrichtung addierten Grundneigung. Formulierte Silhouetten sind abgewandte Hänge, die der erhöhte Blick sichtbar macht (die Kandidatenmenge); sie bleiben erhalten, wo der Neigungsfilter sie für bedeutsam hält (außerhalb der schwach/schwach-Ecke von Spalten- gegen Zeilenneigung), werden auf die vom Betrachter entfernteste Zelle ausgedünnt und über die Profile verkettet.

Die Höhen des DGM müssen in Metern vorliegen und sein KBS in Metern projiziert sein; ein geographisches DGM wird abgelehnt. Jede Blickrichtung ist möglich; die vier Haupthimmelsrichtungen sind exakt.

Zwei Linienausgaben: Faktische Silhouetten (fett schwarz, Breite nach verdeckter Tiefe) und Formulierte Silhouetten (dünner sepia, Breite nach Neigung). Getrennte Layer, damit jeder für sich gestaltet, gefiltert oder ausgeblendet und in Modellen getrennt weitergeleitet werden kann. Jeder Strich trägt: class, cells, length, mean_slope und mean_row_slope (%), mean_depth und max_depth (m, nur faktisch), mean_dist (Abstand im Gelände vom vorderen Bildrand, in der Einheit des KBS) und mean_z (m).

Die Striche werden standardmäßig gezeichnet, wie sie ein Kartograf veröffentlichen würde: verbunden, wo sie einander fortsetzen, innerhalb einer Zelle der exakten Kette geglättet und als LineString M gespeichert, deren M-Werte jeden Punkt gewichten (dünn an den Enden, dünner zum hinteren Rand der Ansicht); die Stile zeichnen diese Gewichte. Der erweiterte Parameter Striche liefert stattdessen die exakten Striche der Dissertation.

Die Stufenkennzahlen (Protokoll und Ausgaben), in Prozent der Zellen mit Daten: HIDDEN_PCT (hinter näherem Gelände verdeckte Zellen), OCCLUDING_PCT (verdeckende Zellen), CSET_PCT (die Kandidatenmenge: abgewandte Zellen, die der erhöhte Blick sichtbar macht), FSET_PCT (die gefilterte Menge: sichtbare Kandidaten, die der Neigungsfilter behält), TSET_PCT (die ausgedünnte Menge: eine Zelle je gefilterter Zone) und GSET_PCT (die generalisierte Menge: Zellen der behaltenen Striche, die mindestens die Mindestzahl an Zellen haben); FACTUAL_STROKES und FORMULATED_STROKES zählen die Striche.

Quelle: Beyond Factual to Formulated Silhouettes, Dissertation, Department of Computer Science, University of Hull (Kapitel 4 und 5), als Erweiterung der Verdeckungskonturen von Visvalingam und Whelan (1998).</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="116" />
        <source>Chaining window (cells)</source>
        <translation>Verkettungsfenster (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="117" />
        <source>Formulated strokes link cells on neighbouring profiles at most this many cells apart.</source>
        <translation>Formulierte Striche verbinden Zellen benachbarter Profile, die höchstens so viele Zellen auseinander liegen.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="118" />
        <source>Minimum stroke cells</source>
        <translation>Mindestzahl Zellen je Strich</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="119" />
        <source>Strokes with fewer cells are dropped (generalisation). Drawn strokes keep shorter pieces only where they close a gap between longer ones.</source>
        <translation>Striche mit weniger Zellen werden verworfen (Generalisierung). Gezeichnete Striche behalten kürzere Stücke nur, wo sie eine Lücke zwischen längeren schließen.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="123" />
        <source>Formulated stroke placement</source>
        <translation>Lage der formulierten Striche</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="125" />
        <source>Far end of each zone</source>
        <translation>Hinteres Ende jeder Zone</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="125" />
        <source>Near and far ends</source>
        <translation>Vorderes und hinteres Ende</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="128" />
        <source>Which cells of a filtered zone become formulated silhouette points.</source>
        <translation>Welche Zellen einer gefilterten Zone zu Punkten formulierter Silhouetten werden.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="129" />
        <source>Sub-cell occluding points</source>
        <translation>Verdeckungspunkte zwischen Zellen</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="130" />
        <source>Place factual points where the transformed profile peaks between cells instead of at cell centres (removes the thesis's halo).</source>
        <translation>Faktische Punkte dort setzen, wo das transformierte Profil zwischen den Zellen seinen Gipfel hat, statt in die Zellmitte (beseitigt den Halo der Dissertation).</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="134" />
        <source>Profiles per strip (0: automatic)</source>
        <translation>Profile je Streifen (0: automatisch)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="135" />
        <source>The DEM is read and processed this many profiles at a time, the next strip read while this one is processed, so DEMs larger than memory run too. 0 chooses 1024, more for profiles under 1024 cells (a million cells a strip), fewer for profiles over 4096 cells (four million cells a strip, at least 256), or fewer when profiles are so long that the strips would take more than 512 MB. Strips that would take more than half of this machine's memory are refused.</source>
        <translation>Das DGM wird so viele Profile auf einmal gelesen und verarbeitet, der nächste Streifen wird gelesen, während dieser verarbeitet wird; so laufen auch DGM, die größer als der Speicher sind. 0 wählt 1024, mehr für Profile unter 1024 Zellen (eine Million Zellen je Streifen), weniger für Profile über 4096 Zellen (vier Millionen Zellen je Streifen, mindestens 256), oder weniger, wenn die Profile so lang sind, dass die Streifen mehr als 512 MB belegen würden. Streifen, die mehr als die Hälfte des Arbeitsspeichers dieses Rechners belegen würden, werden abgelehnt.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="142" />
        <source>Factual silhouettes</source>
        <translation>Faktische Silhouetten</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="143" />
        <source>Occluding contours as line strokes.</source>
        <translation>Verdeckungskonturen als Linienstriche.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="144" />
        <source>Formulated silhouettes</source>
        <translation>Formulierte Silhouetten</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="145" />
        <source>Formulated silhouettes as line strokes.</source>
        <translation>Formulierte Silhouetten als Linienstriche.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="159" />
        <source>Drawn (the default): strokes a cartographer would publish. Pieces of one class that continue each other across a small gap are joined before short strokes are dropped; points lie between cells where the profile peaks or the slope breaks, and are smoothed along the stroke; every point carries a weight (its M value) that tapers the ends and thins the strokes towards the back of the view, which the layers' styles draw. Exact: the thesis's strokes, a point at each cell centre.</source>
        <translation>Gezeichnet (Voreinstellung): Striche, wie sie ein Kartograf veröffentlichen würde. Stücke einer Klasse, die einander über eine kleine Lücke fortsetzen, werden verbunden, bevor kurze Striche entfallen; Punkte liegen zwischen den Zellen, wo das Profil gipfelt oder die Neigung bricht, und werden entlang des Strichs geglättet; jeder Punkt trägt ein Gewicht (seinen M-Wert), das die Enden verjüngt und die Striche zum hinteren Rand der Ansicht hin dünner macht, wie es die Stile der Layer zeichnen. Exakt: die Striche der Dissertation, ein Punkt in jeder Zellmitte.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="165" />
        <source>Drawn for scale</source>
        <translation>Gezeichnet für Maßstab</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="170" />
        <source>Drawn strokes: the scale of the map they are drawn for (1:N). The shortest stroke (2 mm on paper), the smoothing, its tolerance and the join gap become at least what that scale needs, strokes outlining less than N/10 000 metres of relief are left out, and the layers' styles draw their widths true at that scale (the renderer's reference scale). A DEM at least twice as fine as the scale needs (cells under 0.4 mm on paper) is first averaged to it. Empty: for no scale; every stroke is still weighed by the relief it outlines.</source>
        <translation>Gezeichnete Striche: der Maßstab der Karte, für die sie gezeichnet werden (1:N). Der kürzeste Strich (2 mm auf dem Papier), die Glättung, ihre Toleranz und die Verbindungslücke werden mindestens so groß, wie dieser Maßstab es verlangt; Striche, die weniger als N/10 000 Meter Relief umreißen, entfallen, und die Stile der Layer zeichnen ihre Breiten in diesem Maßstab wahr (der Bezugsmaßstab des Renderers). Ein DGM, das mindestens doppelt so fein ist, wie der Maßstab es verlangt (Zellen unter 0,4 mm auf dem Papier), wird zuerst darauf gemittelt. Leer: für keinen Maßstab; jeder Strich wird dennoch nach dem Relief gewichtet, das er umreißt.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="177" />
        <source>Join gap (cells)</source>
        <translation>Verbindungslücke (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="178" />
        <source>Drawn strokes: ends of two strokes this close (in cells) are joined when their directions agree. 0 joins none.</source>
        <translation>Gezeichnete Striche: Enden zweier Striche, die so nahe beieinander liegen (in Zellen), werden verbunden, wenn ihre Richtungen übereinstimmen. 0 verbindet keine.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="180" />
        <source>Join angle (degrees)</source>
        <translation>Verbindungswinkel (Grad)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="181" />
        <source>Drawn strokes: the largest turn between two ends' directions, and the step between them, for them to be joined.</source>
        <translation>Gezeichnete Striche: die größte Drehung zwischen den Richtungen zweier Enden und dem Schritt zwischen ihnen, bei der sie noch verbunden werden.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="183" />
        <source>Smoothing (cells)</source>
        <translation>Glättung (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="184" />
        <source>Drawn strokes: the width (sigma, in cells) of the Gaussian smoothing along each stroke. 0 keeps the points where they are.</source>
        <translation>Gezeichnete Striche: die Breite (Sigma, in Zellen) der Gaußschen Glättung entlang jedes Strichs. 0 lässt die Punkte, wo sie sind.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="186" />
        <source>Smoothing tolerance (cells)</source>
        <translation>Glättungstoleranz (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="187" />
        <source>Drawn strokes: no point moves farther than this (in cells) from its place on the exact chain, so smoothing never invents terrain.</source>
        <translation>Gezeichnete Striche: kein Punkt liegt weiter als dies (in Zellen) von seinem Platz auf der exakten Kette, so dass die Glättung nie Gelände erfindet.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="189" />
        <source>Taper (share of the stroke)</source>
        <translation>Verjüngung (Anteil des Strichs)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="190" />
        <source>Drawn strokes: the share of a stroke's length over which each end thins.</source>
        <translation>Gezeichnete Striche: der Anteil der Strichlänge, über den jedes Ende dünner wird.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="191" />
        <source>Depth cue</source>
        <translation>Tiefenwirkung</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="192" />
        <source>Drawn strokes: the share of the weight strokes lose from the front of the view to its back.</source>
        <translation>Gezeichnete Striche: der Anteil des Gewichts, den Striche vom vorderen zum hinteren Rand der Ansicht verlieren.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="194" />
        <source>Over-extension (cells)</source>
        <translation>Überzeichnung (Zellen)</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="195" />
        <source>Drawn strokes: each end runs on this far (in cells) along its direction, as a hand-drawn stroke does. 0: none.</source>
        <translation>Gezeichnete Striche: jedes Ende läuft so weit (in Zellen) in seiner Richtung weiter, wie es ein von Hand gezeichneter Strich tut. 0: keine.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="243" />
        <source>Processing the DEM in %1 strips of %2 profiles.</source>
        <translation>Das DGM wird in %1 Streifen zu je %2 Profilen verarbeitet.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="284" />
        <source>Drawn for 1:%L1, the DEM was averaged %L2 x %L2 cells first (to %L3 m a cell, about 0.4 mm on paper): the scale shows nothing finer.</source>
        <translation>Gezeichnet für 1:%L1: das DGM wurde zuerst über %L2 x %L2 Zellen gemittelt (auf %L3 m je Zelle, etwa 0,4 mm auf dem Papier); feiner zeigt der Maßstab nichts.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="297" />
        <source>No strokes: every cell of the DEM is nodata (its declared nodata value, NaN, or a height of 1e30 or more): check the band, the no data value the layer or its file declares (Layer Properties &gt; Transparency), and the band's scale.</source>
        <translation>Keine Striche: jede Zelle des DGM ist NoData (sein angegebener NoData-Wert, NaN oder eine Höhe von 1e30 oder mehr): prüfen Sie das Band, den NoData-Wert, den der Layer oder seine Datei angibt (Layereigenschaften &gt; Transparenz), und die Skalierung des Bands.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="303" />
        <source>No strokes: no cell of the DEM is hidden, and none slopes away from the viewer gently enough to be seen once tilted (under the base slope of %L1 % over the exaggeration of %L2, %L3 %): the DEM is flat, or faces the viewer everywhere. Another view azimuth or a larger base slope brings slopes into sight.</source>
        <translation>Keine Striche: keine Zelle des DGM ist verdeckt, und keine fällt vom Betrachter so sanft ab, dass sie nach dem Kippen zu sehen ist (unter der Grundneigung von %L1 % geteilt durch die Überhöhung von %L2, %L3 %): das DGM ist flach oder überall dem Betrachter zugewandt. Eine andere Blickrichtung oder eine größere Grundneigung bringt Hänge in Sicht.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="313" />
        <source>No strokes: the slope filter removed every candidate cell, and no cell is hidden. Lower cut-offs keep more, or the slope filter adapted to the DEM scales them.</source>
        <translation>Keine Striche: der Neigungsfilter hat jede Kandidatenzelle entfernt, und keine Zelle ist verdeckt. Niedrigere Grenzwerte behalten mehr, oder der an das DGM angepasste Neigungsfilter skaliert sie.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="320" />
        <source>No strokes: every chain was shorter than the shortest stroke kept. Drawn for 1:%1, strokes under %L2 mm on paper, or outlining under %L3 m of relief, are dropped too: a larger scale (a smaller number) keeps more.</source>
        <translation>Keine Striche: jede Kette war kürzer als der kürzeste behaltene Strich. Gezeichnet für 1:%1 entfallen auch Striche unter %L2 mm auf dem Papier oder solche, die weniger als %L3 m Relief umreißen: ein größerer Maßstab (eine kleinere Zahl) behält mehr.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="326" />
        <source>No strokes: every chain was shorter than the shortest stroke kept (%L1 cells). A lower minimum stroke length keeps more.</source>
        <translation>Keine Striche: jede Kette war kürzer als der kürzeste behaltene Strich (%L1 Zellen). Eine geringere Mindestzahl Zellen je Strich behält mehr.</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="340" />
        <source>Factual silhouettes, %1</source>
        <translation>Faktische Silhouetten, %1</translation>
    </message>
    <message>
        <location filename="../plugin/silhouettes_algorithm.cpp" line="343" />
        <source>Formulated silhouettes, %1</source>
        <translation>Formulierte Silhouetten, %1</translation>
    </message>
</context>
<context>
    <name>TaperedLine</name>
    <message>
        <location filename="../plugin/tapered_line.cpp" line="37" />
        <source>&lt;h3&gt;terrain_sketch_draws_taper()&lt;/h3&gt;&lt;div&gt;True while the Terrain Sketch plugin is loaded and draws the width of every vertex of drawn strokes. Its styles' stepped lines are enabled only where it is unknown.&lt;/div&gt;</source>
        <translation>&lt;h3&gt;terrain_sketch_draws_taper()&lt;/h3&gt;&lt;div&gt;Wahr, solange die Erweiterung Terrain Sketch geladen ist und die Breite jedes Stützpunkts gezeichneter Striche zeichnet. Die gestuften Linien ihrer Stile sind nur dort aktiv, wo die Funktion unbekannt ist.&lt;/div&gt;</translation>
    </message>
    <message>
        <location filename="../plugin/tapered_line.cpp" line="171" />
        <source>Tapered line (Terrain Sketch)</source>
        <translation>Verjüngte Linie (Terrain Sketch)</translation>
    </message>
</context>
<context>
    <name>TerrainSketchProvider</name>
    <message>
        <location filename="../plugin/provider.cpp" line="21" />
        <source>Terrain sketch</source>
        <translation>Geländeskizze</translation>
    </message>
    <message>
        <location filename="../plugin/provider.cpp" line="24" />
        <source>Terrain sketch: factual and formulated silhouettes</source>
        <translation>Geländeskizze: faktische und formulierte Silhouetten</translation>
    </message>
</context>
<context>
    <name>tsk::plugin</name>
    <message>
        <location filename="../plugin/run_notes.cpp" line="23" />
        <source>%1: row %L2 %, column %L3 %, control point %L4 %</source>
        <translation>%1: Zeile %L2 %, Spalte %L3 %, Kontrollpunkt %L4 %</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="24" />
        <source>the thesis's slope filter</source>
        <translation>der Neigungsfilter der Dissertation</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="25" />
        <source>the slope filter adapted to the DEM</source>
        <translation>der an das DGM angepasste Neigungsfilter</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="30" />
        <source>from %L1°</source>
        <translation>von %L1°</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="36" />
        <source>drawn strokes for 1:%L1</source>
        <translation>gezeichnete Striche für 1:%L1</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="39" />
        <source> from the DEM averaged %L1 x %L1 cells</source>
        <translation> aus dem DGM, gemittelt über %L1 x %L1 Zellen</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="40" />
        <source>%1. Seen from %L2° (azimuth), vertical exaggeration %L3, base slope %L4 %; %5; %6. Terrain Sketch %7.</source>
        <translation>%1. Gesehen aus %L2° (Azimut), Überhöhung %L3, Grundneigung %L4 %; %5; %6. Terrain Sketch %7.</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="50" />
        <source>; %L1 samples per cell along each ray</source>
        <translation>; %L1 Abtastpunkte je Zelle entlang jedes Strahls</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="37" />
        <source>drawn strokes</source>
        <translation>gezeichnete Striche</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="43" />
        <source>the thesis's exact strokes</source>
        <translation>die exakten Striche der Dissertation</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="54" />
        <source>to the same scale as azimuths</source>
        <translation>im selben Maßstab wie die Azimute</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="55" />
        <source>%L1 times as tall as azimuths are wide</source>
        <translation>%L1-mal so hoch, wie Azimute breit sind,</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="56" />
        <source>%1. Seen from %L2, %L3, %L4 m above the ground, from %L5° to %L6° (azimuths from grid north); elevation angles drawn %7%9. Terrain Sketch %8.</source>
        <translation>%1. Gesehen von %L2, %L3, %L4 m über dem Boden, von %L5° bis %L6° (Azimute von Gitternord); Höhenwinkel %7 gezeichnet%9. Terrain Sketch %8.</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="67" />
        <source>%1. %2 seen from %L3° (azimuth), vertical exaggeration %L4, base slope %L5 %</source>
        <translation>%1. %2, gesehen aus %L3° (Azimut), Überhöhung %L4, Grundneigung %L5 %</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="71" />
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../plugin/run_notes.cpp" line="73" />
        <source>. Terrain Sketch %1.</source>
        <translation>. Terrain Sketch %1.</translation>
    </message>
</context>
</TS>