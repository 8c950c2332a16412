"""German translations of cad2osmag, keyed by the English source text (``update_ts.py`` reads them).

Terms: area = Fläche, passage = Durchgang, floor plan = Grundriss, level = Geschoss, stairs = Treppe,
lift/elevator = Aufzug, corridor = Flur, doorway = Türöffnung, control points = Passpunkte, CRS = KBS.
Parameter ids (INPUT, LEVEL, …), field names and tag values stay English; keep {} placeholders in order.
A key may also be ``("Context", "source")`` for a context-specific translation.
"""

T = {
    # --- Cad2OsmagPlugin
    "Convert a DXF floor plan to osmAG…": "DXF-Grundriss in osmAG umwandeln…",
    "Show the CAD to osmAG algorithms": "Die CAD-zu-osmAG-Algorithmen anzeigen",
    "Convert a floor plan…": "Einen Grundriss umwandeln…",
    "Place a floor plan on the map…": "Einen Grundriss auf der Karte platzieren…",
    "Add OpenStreetMap basemap": "OpenStreetMap-Hintergrundkarte hinzufügen",
    "Add satellite imagery basemap": "Satellitenbild-Hintergrundkarte hinzufügen",
    "Added basemap “{}”.": "Hintergrundkarte „{}“ hinzugefügt.",
    # --- AssignNamesAlgorithm
    "Assign room names and types from texts": "Raumnamen und -typen aus Texten zuweisen",
    "Pipeline": "Verarbeitungskette",
    ("Names, numbers and types the AREAS from the drawing's TEXTS (the text output of 'Extract structure "
     "from DXF', with block attributes).\n"
     "Which texts are room names: configurable rules (NAME_RULES, a copy of "
     "algorithms/default_name_rules.json) classify every text as a room name, a room number (kept as ref) "
     "or ignored, with the reason (dimension, area, elevation, door/window code, axis, stair arrow, note, "
     "title, title block, furniture...), using the text itself, the layer it sits on (room-name layers such "
     "as A-ANNO-ROOM, *-SYMB-NAME, 房间; bound-xref prefixes are stripped) and its block and attribute tag. "
     "Lines of a multi-line TEXT label are joined first.\n"
     "Which area: every text is scored against every area as in the CAD-to-osmAG paper (inside: 100 - 50 "
     "rho up to rho_max 0.7, then 50 - 25 (rho - 0.7); outside but within 2.2 m of the border: 40 + 30 "
     "f_size + 20 f_dist) and goes to its best area; a text inside an area belongs to it. Name and number "
     "join; an area holding two different room names is split at the narrowing between them (SPLIT, "
     "grown from the cores of its clearance map; a corridor between them becomes its own area), else it keeps the "
     "best-placed name and lists the others in label_conflict. Duplicate names get a suffix (the room "
     "number, else (1), (2)...); areas without text get the stable id level-area id (e.g. 2-17).\n"
     "Types: keywords (English, Italian, Spanish, German, French, Chinese...) and codes (*-ST-* stairs, "
     "*-P1/*-OP-*/*-FG-* lifts) set type stairs/elevator/corridor/room and the Simple Indoor Tagging fields "
     "indoor and room; long, narrow unnamed areas with three or more passages become corridors.\n"
     "Edit name, ref or type in the output layer to fix them: 'Export osmAG' keeps the edits and the "
     "passages follow renamed areas. TEXT_REPORT (optional) lists every label with its role, reason, area "
     "and score.\n"
     "PASSAGES (optional): the passages of the areas; split areas get theirs, and corridors are recognised "
     "by their number of passages. LEVEL: the level used in generated ids (empty: the areas' level field, "
     "else 1).\n"
     "Outputs: OUTPUT_AREAS, the named areas (fields name, ref, type, indoor, room, label_conflict); "
     "OUTPUT_PASSAGES, the passages including those of split areas; counts NAMED (areas named from the "
     "drawing), NUMBERED (with a room number), AUTO_IDS (with a generated id), CONFLICTS (holding several "
     "names), SPLITS (areas split), IGNORED (texts ignored) and OUTSIDE (room texts outside every area)."):
        ("Benennt, nummeriert und typisiert die AREAS (Flächen) anhand der TEXTS der Zeichnung (die "
         "Textausgabe von „Bauteile aus DXF extrahieren“, mit Blockattributen).\n"
         "Welche Texte Raumnamen sind: konfigurierbare Regeln (NAME_RULES, eine Kopie von "
         "algorithms/default_name_rules.json) ordnen jeden Text als Raumname, Raumnummer (als ref "
         "übernommen) oder ignoriert ein, mit Begründung (Bemaßung, Fläche, Höhenkote, Tür-/Fensterkennung, "
         "Achse, Treppenpfeil, Notiz, Titel, Schriftfeld, Möbel …), anhand des Textes selbst, des Layers, "
         "auf dem er liegt (Raumnamen-Layer wie A-ANNO-ROOM, *-SYMB-NAME, 房间; Präfixe gebundener externer "
         "Referenzen werden entfernt), sowie seines Blocks und Attribut-Tags. Die Zeilen eines mehrzeiligen "
         "TEXT-Labels werden zuerst zusammengefügt.\n"
         "Welche Fläche: Jeder Text wird wie im CAD-to-osmAG-Artikel gegen jede Fläche bewertet (innen: 100 "
         "- 50 rho bis rho_max 0.7, danach 50 - 25 (rho - 0.7); außen, aber höchstens 2.2 m vom Rand: 40 + "
         "30 f_size + 20 f_dist) und geht an seine beste Fläche; ein Text innerhalb einer Fläche gehört zu "
         "ihr. Name und Nummer werden verbunden; eine Fläche mit zwei verschiedenen Raumnamen wird an der "
         "Engstelle zwischen ihnen geteilt (SPLIT, von den Kernen ihrer Freiraumkarte aus gewachsen; ein Flur dazwischen "
         "wird eine eigene Fläche), andernfalls behält sie den am besten platzierten Namen und führt die "
         "übrigen in label_conflict auf. Doppelte Namen erhalten einen Zusatz (die Raumnummer, sonst (1), "
         "(2) …); Flächen ohne Text erhalten die stabile Kennung Geschoss-Flächenkennung (z. B. 2-17).\n"
         "Typen: Schlüsselwörter (Englisch, Italienisch, Spanisch, Deutsch, Französisch, Chinesisch …) und "
         "Kennungen (*-ST-* Treppen, *-P1/*-OP-*/*-FG-* Aufzüge) setzen den Typ "
         "stairs/elevator/corridor/room und die Simple-Indoor-Tagging-Felder indoor und room; lange, "
         "schmale unbenannte Flächen mit drei oder mehr Durchgängen werden Flure.\n"
         "Zum Korrigieren name, ref oder type in der Ausgabelayer bearbeiten: „osmAG exportieren“ übernimmt "
         "die Änderungen, und die Durchgänge folgen umbenannten Flächen. TEXT_REPORT (optional) listet "
         "jedes Label mit Rolle, Begründung, Fläche und Bewertung.\n"
         "PASSAGES (optional): die Durchgänge der Flächen; geteilte Flächen erhalten ihre eigenen, und "
         "Flure werden an der Zahl ihrer Durchgänge erkannt. LEVEL: das Geschoss in erzeugten Kennungen "
         "(leer: das Feld level der Flächen, sonst 1).\n"
         "Ausgaben: OUTPUT_AREAS, die benannten Flächen (Felder name, ref, type, indoor, room, "
         "label_conflict); OUTPUT_PASSAGES, die Durchgänge einschließlich derer geteilter Flächen; die "
         "Anzahlen NAMED (aus der Zeichnung benannte Flächen), NUMBERED (mit Raumnummer), AUTO_IDS (mit "
         "erzeugter Kennung), CONFLICTS (mit mehreren Namen), SPLITS (geteilte Flächen), IGNORED "
         "(ignorierte Texte) und OUTSIDE (Raumtexte außerhalb jeder Fläche)."),
    "Areas": "Flächen",
    "Texts (from 'Extract structure from DXF')": "Texte (aus „Bauteile aus DXF extrahieren“)",
    "Passages (optional: split areas get their passages, corridors their degree)":
        "Durchgänge (optional: geteilte Flächen erhalten ihre Durchgänge, Flure ihren Grad)",
    "Level (for generated ids; empty: the areas' level field, else 1)":
        "Geschoss (für erzeugte Kennungen; leer: Feld level der Flächen, sonst 1)",
    "Name rules (JSON, empty = built-in defaults)": "Namensregeln (JSON, leer = eingebaute Regeln)",
    "Split areas holding two room names at the narrowing between them":
        "Flächen mit zwei Raumnamen an der Engstelle dazwischen teilen",
    "Named areas": "Benannte Flächen",
    "Passages (with those of split areas)": "Durchgänge (mit denen geteilter Flächen)",
    "Text report (role, reason, area of every label)": "Textbericht (Rolle, Begründung, Fläche jedes Labels)",
    "Areas named from the drawing": "Aus der Zeichnung benannte Flächen",
    "Areas with a room number": "Flächen mit Raumnummer",
    "Areas with a generated id": "Flächen mit erzeugter Kennung",
    "Areas holding several names": "Flächen mit mehreren Namen",
    "Areas split": "Geteilte Flächen",
    "Texts ignored": "Ignorierte Texte",
    "Room texts outside every area": "Raumtexte außerhalb jeder Fläche",
    "AREAS: the input layer cannot be opened": "AREAS: Der Eingabelayer kann nicht geöffnet werden",
    "TEXTS: the input layer cannot be opened": "TEXTS: Der Eingabelayer kann nicht geöffnet werden",
    "TEXTS": "TEXTS",
    "PASSAGES": "PASSAGES",
    "{} is in {} but AREAS is in {}: reproject it to the CRS of AREAS first":
        "{} liegt in {}, AREAS aber in {}: zuerst in das KBS von AREAS umprojizieren",
    ("AREAS is in a geographic CRS (degrees); the scores use metres: run this on the CAD-frame layers "
     "(before georeferencing) or reproject to a projected CRS"):
        ("AREAS liegt in einem geographischen KBS (Grad); die Bewertung rechnet in Metern: auf den Layern "
         "im CAD-System ausführen (vor dem Georeferenzieren) oder in ein projiziertes KBS umprojizieren"),
    "cannot write area {} to the output layer": "Fläche {} kann nicht in den Ausgabelayer geschrieben werden",
    # --- DxfToOsmagAlgorithm
    "Convert DXF/DWG floor plan to osmAG": "DXF/DWG-Grundriss in osmAG umwandeln",
    ("Runs the whole pipeline on one floor (a DXF, or a DWG of AutoCAD R13-2018 read directly): structural "
     "layers of the drawing are kept (walls, columns, glazing, stairs), rasterized, segmented into an Area "
     "Graph of rooms, corridors and the passages between them, refined (simplified polygons with shared "
     "borders) and written as an osmAG file anchored on the Earth. Each step is also available as its own "
     "algorithm for finer control.\n"
     "INPUT: the floor plan (.dxf or .dwg). LAYER_RULES: a JSON file of layer keywords (empty: the built-in "
     "rules; see 'List DXF/DWG layers'). UNITS: the unit the drawing is drawn in (auto: read from the "
     "header and checked for a plausible building size).\n"
     "RESOLUTION: raster pixel size in metres (0.044 m by default; smaller follows thin walls better but is "
     "slower). TOPOLOGY_CELL: the cell size (m) of the segmentation's skeleton and merges (0.088 m, two raster pixels; the outlines keep the raster's pixels; 0 = the raster's pixels, slower). DOOR_WIDTH: the widest door in metres (2.8 m): narrower openings separate rooms. "
     "CORRIDOR_WIDTH: corridor width in metres (8 m). MIN_AREA: areas smaller than this (m²) merge into a "
     "neighbour (stairs and lifts are kept). INCLUDE_DOORS: draw door layers as walls (doorways closed; off "
     "by default, so that doorways stay open).\n"
     "PLAN / PLAN_EXTENT: which plan of a sheet with several (empty: the main plan; an index of the plan "
     "list in the log, or xmin,ymin,xmax,ymax in metres, or an extent drawn on the canvas).\n"
     "NAMES (on by default): the drawing's texts name, number and type the areas (see 'Assign room names "
     "and types from texts'); NAME_RULES: a JSON file that adapts those rules.\n"
     "LEVEL: the floor's level (osmAG level tag, e.g. 1, -1). HEIGHT: floor height in metres (3.2 m). "
     "ANCHOR: where the drawing origin (0, 0) lies on the map (pick it on a basemap; empty: longitude 0, "
     "latitude 0). ROTATION: the direction of the drawing's +y axis in degrees clockwise from north. "
     "VARIANT: semantic (passages name their areas) or fix-id (passages give way ids).\n"
     "Outputs: OUTPUT, the osmAG file (.osm); OUTPUT_AREAS and OUTPUT_PASSAGES, the same areas and passages "
     "as layers in WGS84 to show on the map; PREVIEW, an optional PNG picture of the areas; AREA_COUNT and "
     "PASSAGE_COUNT, the numbers written."):
        ("Führt die ganze Verarbeitungskette für ein Geschoss aus (eine DXF oder eine DWG von AutoCAD "
         "R13-2018, direkt gelesen): Die Bauteil-Layer der Zeichnung werden behalten (Wände, Stützen, "
         "Verglasung, Treppen), gerastert, in einen Area Graph aus Räumen, Fluren und den Durchgängen "
         "dazwischen segmentiert, verfeinert (vereinfachte Polygone mit gemeinsamen Kanten) und als "
         "osmAG-Datei geschrieben, auf der Erde verankert. Jeder Schritt ist auch als eigener Algorithmus "
         "verfügbar, für genauere Kontrolle.\n"
         "INPUT: der Grundriss (.dxf oder .dwg). LAYER_RULES: eine JSON-Datei mit Layer-Schlüsselwörtern "
         "(leer: die eingebauten Regeln; siehe „DXF/DWG-Layer auflisten“). UNITS: die Einheit, in der die "
         "Zeichnung gezeichnet ist (auto: aus dem Dateikopf gelesen und auf eine plausible Gebäudegröße "
         "geprüft).\n"
         "RESOLUTION: Pixelgröße des Rasters in Metern (0.044 m als Vorgabe; kleiner folgt dünnen Wänden "
         "besser, ist aber langsamer). TOPOLOGY_CELL: die Zellgröße (m) von Skelett und Zusammenführungen der Segmentierung (0.088 m, zwei Rasterpixel; die Umrisse behalten die Pixel des Rasters; 0 = die Pixel des Rasters, langsamer). DOOR_WIDTH: die breiteste Tür in Metern (2.8 m): schmalere Öffnungen "
         "trennen Räume. CORRIDOR_WIDTH: Flurbreite in Metern (8 m). MIN_AREA: Flächen kleiner als dieser "
         "Wert (m²) werden mit einer Nachbarfläche zusammengeführt (Treppen und Aufzüge bleiben erhalten). "
         "INCLUDE_DOORS: Tür-Layer als Wände zeichnen (Türöffnungen geschlossen; als Vorgabe aus, damit "
         "Türöffnungen offen bleiben).\n"
         "PLAN / PLAN_EXTENT: welcher Plan eines Blatts mit mehreren (leer: der Hauptplan; ein Index der "
         "Planliste im Protokoll, oder xmin,ymin,xmax,ymax in Metern, oder eine im Kartenfenster "
         "gezeichnete Ausdehnung).\n"
         "NAMES (als Vorgabe an): Die Texte der Zeichnung benennen, nummerieren und typisieren die Flächen "
         "(siehe „Raumnamen und -typen aus Texten zuweisen“); NAME_RULES: eine JSON-Datei, die diese Regeln "
         "anpasst.\n"
         "LEVEL: das Geschoss (osmAG-Tag level, z. B. 1, -1). HEIGHT: Geschosshöhe in Metern (3.2 m). "
         "ANCHOR: wo der Zeichnungsursprung (0, 0) auf der Karte liegt (auf einer Hintergrundkarte wählen; "
         "leer: Längengrad 0, Breitengrad 0). ROTATION: die Richtung der +y-Achse der Zeichnung in Grad im "
         "Uhrzeigersinn von Norden. VARIANT: semantic (Durchgänge nennen ihre Flächen beim Namen) oder "
         "fix-id (Durchgänge geben Weg-Kennungen an).\n"
         "Ausgaben: OUTPUT, die osmAG-Datei (.osm); OUTPUT_AREAS und OUTPUT_PASSAGES, dieselben Flächen und "
         "Durchgänge als Layer in WGS84 zur Anzeige auf der Karte; PREVIEW, ein optionales PNG-Bild der "
         "Flächen; AREA_COUNT und PASSAGE_COUNT, die geschriebenen Anzahlen."),
    "DXF or DWG floor plan": "DXF- oder DWG-Grundriss",
    "Layer rules (JSON, optional)": "Layer-Regeln (JSON, optional)",
    "Drawing units": "Zeichnungseinheiten",
    "Raster resolution (m/px)": "Rasterauflösung (m/px)",
    "Widest door (m)": "Breiteste Tür (m)",
    "Corridor width (m)": "Flurbreite (m)",
    "Merge areas smaller than (m²)": "Flächen zusammenführen, die kleiner sind als (m²)",
    "Close doorways (rasterize door layers)": "Türöffnungen schließen (Tür-Layer rastern)",
    "Room names, numbers and types from the drawing's texts":
        "Raumnamen, -nummern und -typen aus den Texten der Zeichnung",
    "Name rules (JSON, optional)": "Namensregeln (JSON, optional)",
    "Level": "Geschoss",
    "Floor height (m)": "Geschosshöhe (m)",
    "Position of the drawing origin": "Lage des Zeichnungsursprungs",
    "Rotation (degrees clockwise from north)": "Drehung (Grad im Uhrzeigersinn von Norden)",
    "osmAG variant": "osmAG-Variante",
    "osmAG file": "osmAG-Datei",
    "OpenStreetMap XML (*.osm)": "OpenStreetMap-XML (*.osm)",
    "Areas (to show on the map)": "Flächen (zur Anzeige auf der Karte)",
    "Passages (to show on the map)": "Durchgänge (zur Anzeige auf der Karte)",
    "Preview image": "Vorschaubild",
    "PNG image (*.png)": "PNG-Bild (*.png)",
    "Passages": "Durchgänge",
    "OUTPUT: give the .osm file to write": "OUTPUT: die zu schreibende .osm-Datei angeben",
    "Stage times: {}": "Laufzeiten der Schritte: {}",
    "auto": "automatisch",
    "mm": "mm",
    "cm": "cm",
    "m": "m",
    "inch": "Zoll",
    "feet": "Fuß",
    # --- DxfToOsmagBatchAlgorithm
    "Convert a folder of floor plans to osmAG (parallel)":
        "Einen Ordner mit Grundrissen in osmAG umwandeln (parallel)",
    ("Converts every floor plan of FOLDER (files matching PATTERN, e.g. '*.dxf') with the whole pipeline of "
     "'Convert DXF floor plan to osmAG', several files at once: WORKERS processes (0 = one per processor "
     "core). Each file writes OUTPUT_FOLDER/NAME.osm (NAME: the drawing's file name). A file that fails "
     "(not a drawing, no walls, …) is reported with its reason and never stops the others.\n"
     "FIRST_LEVEL: the level of the first file in natural name order (floor-2 before floor-10); each next "
     "file is one level up. HEIGHT: floor height in metres.\n"
     "Placement, the same for every floor: ANCHOR is where the drawing origin (0, 0) lies (pick it on the "
     "map), ROTATION the direction of the drawing's +y axis in degrees clockwise from north, SCALE ground "
     "metres per drawing metre. Without ANCHOR the placement saved in the project by 'Place a floor plan on "
     "the map' is used, if any.\n"
     "RESOLUTION (m/px), DOOR_WIDTH and CORRIDOR_WIDTH (m), MIN_AREA (m²): as in the single-file algorithm. "
     "MERGE also writes OUTPUT_FOLDER/building.osm with every converted floor.\n"
     "REPORT: a CSV with one row per file (file, level, status, areas, passages, seconds, message).\n"
     "Outputs: SUCCEEDED and FAILED, the numbers of floors converted and failed (one bad file never stops "
     "the others), and OUTPUT_FOLDER."):
        ("Wandelt jeden Grundriss in FOLDER (Dateien, die auf PATTERN passen, z. B. '*.dxf') mit der ganzen "
         "Verarbeitungskette von „DXF-Grundriss in osmAG umwandeln“ um, mehrere Dateien gleichzeitig: "
         "WORKERS Prozesse (0 = einer je Prozessorkern). Jede Datei schreibt OUTPUT_FOLDER/NAME.osm (NAME: "
         "der Dateiname der Zeichnung). Eine Datei, die scheitert (keine Zeichnung, keine Wände, …), wird "
         "mit ihrem Grund gemeldet und hält die anderen nie auf.\n"
         "FIRST_LEVEL: das Geschoss der ersten Datei in natürlicher Namensreihenfolge (floor-2 vor "
         "floor-10); jede weitere Datei liegt ein Geschoss höher. HEIGHT: Geschosshöhe in Metern.\n"
         "Platzierung, für jedes Geschoss gleich: ANCHOR ist der Ort des Zeichnungsursprungs (0, 0) (auf "
         "der Karte wählen), ROTATION die Richtung der +y-Achse der Zeichnung in Grad im Uhrzeigersinn von "
         "Norden, SCALE Meter im Gelände je Zeichnungsmeter. Ohne ANCHOR wird die mit „Einen Grundriss auf "
         "der Karte platzieren“ im Projekt gespeicherte Platzierung verwendet, falls vorhanden.\n"
         "RESOLUTION (m/px), DOOR_WIDTH und CORRIDOR_WIDTH (m), MIN_AREA (m²): wie im Algorithmus für eine "
         "Datei. MERGE schreibt zusätzlich OUTPUT_FOLDER/building.osm mit jedem umgewandelten Geschoss.\n"
         "REPORT: eine CSV-Datei mit einer Zeile je Datei (Datei, Geschoss, Status, Flächen, Durchgänge, "
         "Sekunden, Meldung).\n"
         "Ausgaben: SUCCEEDED und FAILED, die Anzahl umgewandelter und gescheiterter Geschosse (eine "
         "fehlerhafte Datei hält die anderen nie auf), und OUTPUT_FOLDER."),
    "Folder of floor plans": "Ordner mit Grundrissen",
    "File name patterns (';' separated)": "Dateinamensmuster (durch ';' getrennt)",
    "Level of the first file": "Geschoss der ersten Datei",
    "Scale (ground metres per drawing metre)": "Maßstab (Meter im Gelände je Zeichnungsmeter)",
    "Parallel processes (0 = every core)": "Parallele Prozesse (0 = alle Kerne)",
    "Also merge the floors into building.osm": "Die Geschosse auch zu building.osm zusammenführen",
    "Output folder": "Ausgabeordner",
    "Report (CSV)": "Bericht (CSV)",
    "CSV files (*.csv)": "CSV-Dateien (*.csv)",
    "Floors converted": "Umgewandelte Geschosse",
    "Floors that failed": "Gescheiterte Geschosse",
    "using the placement saved in the project: {:.7f}, {:.7f}, {:.2f}°":
        "verwende die im Projekt gespeicherte Platzierung: {:.7f}, {:.7f}, {:.2f}°",
    "FOLDER: '{}' is not a folder": "FOLDER: '{}' ist kein Ordner",
    "no file in '{}' matches '{}': check the folder and the pattern":
        "keine Datei in '{}' passt auf '{}': Ordner und Muster prüfen",
    "{} files, {} parallel processes": "{} Dateien, {} parallele Prozesse",
    "merged {} floors into {}": "{} Geschosse zu {} zusammengeführt",
    "{} of {} files failed: {}": "{} von {} Dateien gescheitert: {}",
    "started {} (level {})": "{} gestartet (Geschoss {})",
    "Canceled by the user.": "Vom Benutzer abgebrochen.",
    "exit code {}": "Exit-Code {}",
    "the worker process ended without a result: {}": "der Arbeitsprozess endete ohne Ergebnis: {}",
    "{}: {} areas, {} passages in {:.1f} s -> {}": "{}: {} Flächen, {} Durchgänge in {:.1f} s -> {}",
    "{}: failed: {}": "{}: gescheitert: {}",
    # --- EvaluateSegmentationAlgorithm
    "Evaluate segmentation against ground truth": "Segmentierung mit der Referenz vergleichen",
    "Tools": "Werkzeuge",
    ("Compares the LABELS raster of 'Segment' (area ids, 0 = none) with a ground-truth image of the same "
     "size that paints every room in its own colour (black walls, white or grey outside). For every "
     "ground-truth room the predicted area with the largest overlap is its match: recall and precision of "
     "that match, the Matthews correlation coefficient (MCC) of the two masks over the annotated and "
     "segmented pixels (weighted by room area), and the F1 score of rooms matched one to one at IoU >= "
     "0.5.\n"
     "LABELS: the area id raster written by 'Segment' (one integer per pixel).\n"
     "GROUND_TRUTH: a PNG, BMP or TIFF image with exactly the raster's width and height in pixels.\n"
     "MIN_ROOM_PX: ground-truth colours covering fewer pixels than this are antialiasing or labels, not "
     "rooms, and are ignored (pixels; at 0.05 m/px, 40 px are 0.1 m²).\n"
     "REPORT (optional): a CSV with one row per ground-truth room (colour, pixels, matched area, recall, "
     "precision, IoU).\n"
     "Outputs: MCC, F1, mean RECALL and PRECISION (0-1), the number of ground-truth rooms (GT_ROOMS), "
     "predicted areas (PREDICTED_AREAS) and rooms matched at IoU >= 0.5 (MATCHED)."):
        ("Vergleicht das LABELS-Raster von „Segmentieren“ (Flächenkennungen, 0 = keine) mit einem "
         "Referenzbild gleicher Größe, das jeden Raum in einer eigenen Farbe zeigt (Wände schwarz, außen "
         "weiß oder grau). Für jeden Referenzraum ist die vorhergesagte Fläche mit der größten Überlappung "
         "sein Treffer: Recall und Precision dieses Treffers, der Matthews-Korrelationskoeffizient (MCC) "
         "der beiden Masken über die annotierten und segmentierten Pixel (nach Raumfläche gewichtet) und "
         "der F1-Wert der eins zu eins bei IoU >= 0.5 zugeordneten Räume.\n"
         "LABELS: das von „Segmentieren“ geschriebene Flächenkennungs-Raster (eine Ganzzahl je Pixel).\n"
         "GROUND_TRUTH: ein PNG-, BMP- oder TIFF-Bild mit genau der Breite und Höhe des Rasters in Pixeln.\n"
         "MIN_ROOM_PX: Referenzfarben, die weniger Pixel als dieser Wert bedecken, sind Kantenglättung oder "
         "Beschriftung, keine Räume, und werden ignoriert (Pixel; bei 0.05 m/px sind 40 px 0.1 m²).\n"
         "REPORT (optional): eine CSV-Datei mit einer Zeile je Referenzraum (Farbe, Pixel, zugeordnete "
         "Fläche, Recall, Precision, IoU).\n"
         "Ausgaben: MCC, F1, mittlerer RECALL und mittlere PRECISION (0-1), die Anzahl der Referenzräume "
         "(GT_ROOMS), der vorhergesagten Flächen (PREDICTED_AREAS) und der bei IoU >= 0.5 zugeordneten "
         "Räume (MATCHED)."),
    "Area id raster (LABELS of Segment)": "Flächenkennungs-Raster (LABELS von Segmentieren)",
    "Ground-truth colour image": "Farbiges Referenzbild",
    "Ignore ground-truth colours covering fewer pixels than":
        "Referenzfarben ignorieren, die weniger Pixel bedecken als",
    "Per-room report": "Bericht je Raum",
    "MCC (area-weighted)": "MCC (flächengewichtet)",
    "F1 at IoU >= 0.5": "F1 bei IoU >= 0.5",
    "Mean recall": "Mittlerer Recall",
    "Mean precision": "Mittlere Precision",
    "Ground-truth rooms": "Referenzräume",
    "Predicted areas": "Vorhergesagte Flächen",
    "Rooms matched at IoU >= 0.5": "Bei IoU >= 0.5 zugeordnete Räume",
    "LABELS: the raster cannot be opened": "LABELS: Das Raster kann nicht geöffnet werden",
    "GROUND_TRUTH: '{}' does not exist": "GROUND_TRUTH: '{}' existiert nicht",
    "{} ground-truth rooms, {} predicted areas": "{} Referenzräume, {} vorhergesagte Flächen",
    "recall {:.3f}  precision {:.3f}  MCC {:.3f}  F1 {:.3f}":
        "Recall {:.3f}  Precision {:.3f}  MCC {:.3f}  F1 {:.3f}",
    # --- ExportOsmagAlgorithm
    "Export osmAG (.osm)": "osmAG exportieren (.osm)",
    ("Writes AREAS and PASSAGES (and optional floor/building outlines as structure areas, which become the "
     "osmAG:parent of the areas inside them) as an osmAG file: OpenStreetMap XML that JOSM, GDAL and osmium "
     "open, with one root node, negative ids, closed area ways sharing their border nodes, and passage ways "
     "whose two nodes belong to both areas they join.\n"
     "Georeference: layers in a geographic or projected CRS are converted to WGS84 (the root node is placed "
     "at ANCHOR_LON/ANCHOR_LAT when given, else at the centre of the data). Layers in the CAD frame (no "
     "CRS) are placed with ANCHOR_LON/ANCHOR_LAT (where the CAD origin lies, also the root node), ROTATION "
     "and SCALE; without an anchor the export stops and asks you to georeference first.\n"
     "VARIANT 'semantic' references areas by name (survives JOSM editing), 'fix-id' by way id. The file is "
     "written atomically: a failed export leaves no file behind. Holes (pillars) are not part of an osmAG "
     "area way and are left out (counted in the log).\n"
     "STRUCTURE (optional): polygons of the floor or building outline, written as structure areas.\n"
     "LEVEL: the level tag of every area and passage (e.g. 1, -1); empty keeps the layers' own level field, "
     "else 1. HEIGHT: height per level in metres (height tag).\n"
     "ANCHOR_LON / ANCHOR_LAT in degrees (WGS84), ROTATION in degrees clockwise from north, SCALE in ground "
     "metres per CAD metre: the placement of 'Place a floor plan on the map' gives all four.\n"
     "OUTPUT: the .osm file to write.\n"
     "Outputs: AREA_COUNT, PASSAGE_COUNT and NODE_COUNT written; SHARED_NODES, the nodes shared by two or "
     "more areas; HOLES_DROPPED, the holes of areas left out (osmAG areas have no holes)."):
        ("Schreibt AREAS und PASSAGES (und optional Geschoss-/Gebäudeumrisse als Strukturflächen, die zum "
         "osmAG:parent der Flächen darin werden) als osmAG-Datei: OpenStreetMap-XML, das JOSM, GDAL und "
         "osmium öffnen, mit einem Wurzelknoten, negativen Kennungen, geschlossenen Flächenwegen, die ihre "
         "Randknoten teilen, und Durchgangswegen, deren zwei Knoten zu beiden verbundenen Flächen gehören.\n"
         "Georeferenzierung: Layer in einem geographischen oder projizierten KBS werden nach WGS84 "
         "umgerechnet (der Wurzelknoten liegt bei ANCHOR_LON/ANCHOR_LAT, falls angegeben, sonst in der "
         "Mitte der Daten). Layer im CAD-System (ohne KBS) werden mit ANCHOR_LON/ANCHOR_LAT (wo der "
         "CAD-Ursprung liegt, zugleich der Wurzelknoten), ROTATION und SCALE platziert; ohne Anker bricht "
         "der Export ab und bittet, zuerst zu georeferenzieren.\n"
         "VARIANT 'semantic' verweist auf Flächen über den Namen (übersteht Bearbeitung in JOSM), 'fix-id' "
         "über die Weg-Kennung. Die Datei wird atomar geschrieben: Ein gescheiterter Export hinterlässt "
         "keine Datei. Löcher (Stützen) gehören nicht zu einem osmAG-Flächenweg und werden weggelassen (im "
         "Protokoll gezählt).\n"
         "STRUCTURE (optional): Polygone des Geschoss- oder Gebäudeumrisses, als Strukturflächen "
         "geschrieben.\n"
         "LEVEL: das Tag level jeder Fläche und jedes Durchgangs (z. B. 1, -1); leer übernimmt das Feld "
         "level der Layer, sonst 1. HEIGHT: Höhe je Geschoss in Metern (Tag height).\n"
         "ANCHOR_LON / ANCHOR_LAT in Grad (WGS84), ROTATION in Grad im Uhrzeigersinn von Norden, SCALE in "
         "Metern im Gelände je CAD-Meter: Die Platzierung von „Einen Grundriss auf der Karte platzieren“ "
         "liefert alle vier.\n"
         "OUTPUT: die zu schreibende .osm-Datei.\n"
         "Ausgaben: AREA_COUNT, PASSAGE_COUNT und NODE_COUNT geschrieben; SHARED_NODES, die von zwei oder "
         "mehr Flächen geteilten Knoten; HOLES_DROPPED, die weggelassenen Löcher von Flächen (osmAG-Flächen "
         "haben keine Löcher)."),
    "Floor / building outlines (structure areas)": "Geschoss-/Gebäudeumrisse (Strukturflächen)",
    "Level (empty: the areas' own level field, else 1)": "Geschoss (leer: das Feld level der Flächen, sonst 1)",
    "Height per level (m)": "Höhe je Geschoss (m)",
    "Variant": "Variante",
    "semantic (names)": "semantic (Namen)",
    "fix-id (way ids)": "fix-id (Weg-Kennungen)",
    "Anchor / root longitude (CAD-frame layers: where the CAD origin lies)":
        "Längengrad des Ankers / Wurzelknotens (Layer im CAD-System: wo der CAD-Ursprung liegt)",
    "Anchor / root latitude": "Breitengrad des Ankers / Wurzelknotens",
    "Rotation of CAD-frame layers (degrees clockwise from north)":
        "Drehung der Layer im CAD-System (Grad im Uhrzeigersinn von Norden)",
    "Scale of CAD-frame layers": "Maßstab der Layer im CAD-System",
    "Areas written": "Geschriebene Flächen",
    "Passages written": "Geschriebene Durchgänge",
    "Nodes written": "Geschriebene Knoten",
    "Nodes shared by 2+ areas": "Von 2+ Flächen geteilte Knoten",
    "Holes left out": "Weggelassene Löcher",
    "STRUCTURE": "STRUCTURE",
    "{} is in {} but AREAS is in {}; reproject it to the CRS of AREAS first":
        "{} liegt in {}, AREAS aber in {}; zuerst in das KBS von AREAS umprojizieren",
    ("AREAS holds several levels ({}): export one level at a time (filter the layer, or set LEVEL), then "
     "combine the files with 'Merge osmAG floors into a building'"):
        ("AREAS enthält mehrere Geschosse ({}): ein Geschoss nach dem anderen exportieren (den Layer "
         "filtern oder LEVEL setzen), dann die Dateien mit „osmAG-Geschosse zu einem Gebäude "
         "zusammenführen“ vereinen"),
    "layers are in {}: converting to WGS84": "Layer liegen in {}: Umrechnung nach WGS84",
    ("AREAS has no CRS (CAD frame): georeference the layers first (cad2osmag:georeference), or give "
     "ANCHOR_LON and ANCHOR_LAT (where the CAD origin lies) and ROTATION"):
        ("AREAS hat kein KBS (CAD-System): die Layer zuerst georeferenzieren (cad2osmag:georeference) oder "
         "ANCHOR_LON und ANCHOR_LAT (wo der CAD-Ursprung liegt) und ROTATION angeben"),
    "CAD-frame layers placed with {}": "Layer im CAD-System platziert mit {}",
    # --- Cad2OsmagAlgorithm
    "Plan on the sheet (empty = main plan; an index of the log's plan list, or xmin,ymin,xmax,ymax in metres)":
        ("Plan auf dem Blatt (leer = Hauptplan; ein Index der Planliste im Protokoll, oder "
         "xmin,ymin,xmax,ymax in Metern)"),
    "Plan extent (drawn on the canvas over the extracted structure; wins over PLAN)":
        "Planausdehnung (im Kartenfenster über den extrahierten Bauteilen gezeichnet; hat Vorrang vor PLAN)",
    # --- ExtractStructureAlgorithm
    "Extract structure from DXF/DWG": "Bauteile aus DXF/DWG extrahieren",
    ("Reads INPUT, a DXF floor plan or a DWG (AutoCAD R13-2018, read directly: no converter needed), "
     "explodes blocks (with scale, rotation, mirror and MINSERT arrays; entities on layer 0 inside a block "
     "take the INSERT's layer), skips frozen and off layers, keeps the structural layers chosen by the "
     "layer rules (walls, columns, windows/glazing, stairs, lifts, and the reference layers 0 and "
     "Defpoints) and flattens curves to 1 cm.\n"
     "LAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). "
     "LAYERS: explicit layer names (separated by ';') that override the rules. UNITS: the header's "
     "$INSUNITS is only a hint; by default the unit is chosen so that the building is 5-500 m across (a "
     "warning names both units). Door layers are left out unless INCLUDE_DOORS is set, so that doorways "
     "stay open; door swings and door blocks (by name, in many languages) are found on any layer and "
     "written as DOORS (jamb to jamb); furniture blocks, free-standing furniture on layer 0 and pattern "
     "hatches are left out (the log counts every class).\n"
     "Whole sheets: title frames, title blocks and legends are left out and the structure is grouped into "
     "plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists every "
     "group with its index, extent, title and kind (plan / detail / legend). PLAN picks another (an index, "
     "or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.\n"
     "Outputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): WALLS "
     "(lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' rebuilds the "
     "geometry from them; block, class), TEXTS (points with text, height, rotation, layer, entity, block, "
     "tag = ATTRIB tag, id; 'Assign room names and types from texts' reads them) and DOORS (doorway lines "
     "with source and width). Figures: PLANS (the plans found on the sheet) and PLAN_COUNT (their number), "
     "DOOR_COUNT (doorways found), CLASSES (entities counted per class), UNIT and UNIT_SCALE (the unit used "
     "and metres per drawing unit), GEOMETRY_COUNT (structure features written) and TEXT_COUNT (texts "
     "written)."):
        ("Liest INPUT, einen DXF-Grundriss oder eine DWG (AutoCAD R13-2018, direkt gelesen: kein Konverter "
         "nötig), löst Blöcke auf (mit Skalierung, Drehung, Spiegelung und MINSERT-Anordnungen; Objekte auf "
         "Layer 0 in einem Block übernehmen den Layer des INSERT), überspringt gefrorene und ausgeschaltete "
         "Layer, behält die von den Layer-Regeln gewählten Bauteil-Layer (Wände, Stützen, "
         "Fenster/Verglasung, Treppen, Aufzüge sowie die Referenzlayer 0 und Defpoints) und zerlegt Kurven "
         "auf 1 cm genau.\n"
         "LAYER_RULES: eine JSON-Datei mit Schlüsselwörtern ohne Beachtung der Groß-/Kleinschreibung "
         "(algorithms/default_layer_rules.json kopieren). LAYERS: ausdrückliche Layernamen (durch ';' "
         "getrennt), die die Regeln ersetzen. UNITS: $INSUNITS im Dateikopf ist nur ein Hinweis; als "
         "Vorgabe wird die Einheit so gewählt, dass das Gebäude 5-500 m groß ist (eine Warnung nennt beide "
         "Einheiten). Tür-Layer werden weggelassen, außer INCLUDE_DOORS ist gesetzt, damit Türöffnungen "
         "offen bleiben; Türschwenkbögen und Türblöcke (nach Namen, in vielen Sprachen) werden auf jedem "
         "Layer gefunden und als DOORS geschrieben (von Laibung zu Laibung); Möbelblöcke, frei stehende "
         "Möbel auf Layer 0 und Musterschraffuren werden weggelassen (das Protokoll zählt jede Klasse).\n"
         "Ganze Blätter: Rahmen, Schriftfelder und Legenden werden weggelassen, und die Bauteile werden in "
         "Pläne gruppiert (Gruppen, die mehr als 5 m auseinander liegen); der Hauptplan (größte Wandmasse) "
         "wird behalten, das Protokoll listet jede Gruppe mit Index, Ausdehnung, Titel und Art (Plan / "
         "Detail / Legende). PLAN wählt einen anderen (ein Index, oder xmin,ymin,xmax,ymax in Metern); "
         "PLAN_EXTENT ist dieselbe Ausdehnung, im Kartenfenster gezeichnet.\n"
         "Ausgaben, in Metern im eigenen System der Zeichnung (ein lokales technisches KBS, nicht "
         "georeferenziert): WALLS (Linien mit den Feldern layer, kind, entity, closed, filled, width; "
         "„Bauteile rastern“ baut daraus die Geometrie auf; block, class), TEXTS (Punkte mit text, height, "
         "rotation, layer, entity, block, tag = ATTRIB-Tag, id; „Raumnamen und -typen aus Texten zuweisen“ "
         "liest sie) und DOORS (Türöffnungslinien mit source und width). Kennzahlen: PLANS (die auf dem "
         "Blatt gefundenen Pläne) und PLAN_COUNT (ihre Anzahl), DOOR_COUNT (gefundene Türöffnungen), "
         "CLASSES (Objekte je Klasse gezählt), UNIT und UNIT_SCALE (die verwendete Einheit und Meter je "
         "Zeichnungseinheit), GEOMETRY_COUNT (geschriebene Bauteilobjekte) und TEXT_COUNT (geschriebene "
         "Texte)."),
    "DXF or DWG drawing": "DXF- oder DWG-Zeichnung",
    "Layer rules (JSON, empty = built-in defaults)": "Layer-Regeln (JSON, leer = eingebaute Regeln)",
    "Layers to keep (';' separated, overrides the rules)":
        "Zu behaltende Layer (durch ';' getrennt, ersetzt die Regeln)",
    "automatic (header + plausibility)": "automatisch (Dateikopf + Plausibilität)",
    "Include doors (rasterize doorways as closed)": "Türen einbeziehen (Türöffnungen geschlossen rastern)",
    "Structure lines": "Bauteillinien",
    "Texts": "Texte",
    "Doorways found (door swings and door blocks)": "Gefundene Türöffnungen (Türschwenkbögen und Türblöcke)",
    "Plans found on the sheet": "Auf dem Blatt gefundene Pläne",
    "Number of groups found on the sheet": "Anzahl der auf dem Blatt gefundenen Gruppen",
    "Number of doorways found": "Anzahl gefundener Türöffnungen",
    "Entity counts per class": "Objektanzahl je Klasse",
    "Unit used": "Verwendete Einheit",
    "Drawing units to metres": "Zeichnungseinheiten in Metern",
    "Number of structure features": "Anzahl der Bauteilobjekte",
    "Number of texts": "Anzahl der Texte",
    "Entity classes: {}; {} doorways found": "Objektklassen: {}; {} Türöffnungen gefunden",
    "Sheet: {}": "Blatt: {}",
    "Kept {} features on layers: {}; {} texts; unit {} (header: {})":
        "{} Objekte auf den Layern behalten: {}; {} Texte; Einheit {} (Dateikopf: {})",
    # --- Cad2OsmagAlgorithm
    "the point {}, {} [{}] cannot be converted to longitude/latitude: {}":
        "der Punkt {}, {} [{}] kann nicht in Länge/Breite umgerechnet werden: {}",
    # --- GeoreferenceAlgorithm
    "Georeference (place the plan on the map)": "Georeferenzieren (Plan auf der Karte platzieren)",
    ("Transforms layers drawn in the CAD frame (metres, no CRS) into a target CRS (default WGS84).\n"
     "Mode 'Anchor': pick ANCHOR on the map canvas (any CRS) for the CAD point CAD_ANCHOR_X/Y (default the "
     "drawing origin); ROTATION is the direction of the plan's +y axis in degrees clockwise from north, or "
     "give ROTATION_POINT (a second map point) for the CAD point CAD_ROTATION_X/Y and the rotation is "
     "computed from the two picked points; SCALE is ground metres per CAD metre.\n"
     "Mode 'Control points': GCPS is a point layer whose geometry is each point picked against a basemap "
     "and whose fields cad_x, cad_y (or sourceX, sourceY) hold its CAD coordinates; at least 2 points, not "
     "all on one line. A least-squares similarity (Helmert) is solved and the residual of every point and "
     "their RMS are reported in metres.\n"
     "FIX_SCALE keeps SCALE during the fit (solves position and rotation only).\n"
     "AREAS and PASSAGES: layers in the CAD frame (metres, no CRS), e.g. the outputs of 'Refine'; "
     "OUTPUT_AREAS and OUTPUT_PASSAGES get them in TARGET_CRS (default WGS84, EPSG:4326) with all their "
     "fields. MODE chooses 'Anchor point + rotation' or 'Control points'. CAD_ANCHOR_X / CAD_ANCHOR_Y and "
     "CAD_ROTATION_X / CAD_ROTATION_Y are CAD coordinates in metres.\n"
     "All conversions go through a transverse Mercator projection centred on the anchor (pyproj/PROJ), "
     "never a flat-earth approximation. Add a basemap (Vector ▸ CAD to osmAG ▸ Add … basemap) to pick "
     "points against real imagery, or drag the plan into place with Vector ▸ CAD to osmAG ▸ Place a floor "
     "plan on the map, whose placement gives ANCHOR, ROTATION and SCALE.\n"
     "Outputs: RMS and RESIDUALS, the control point residuals in metres (overall and per point); FRAME, the "
     "placement as text; ANCHOR_LON and ANCHOR_LAT (degrees), ROTATION_DEG (degrees clockwise from north) "
     "and SCALE_FACTOR of the placement, to reuse for the other floors."):
        ("Überführt Layer, die im CAD-System gezeichnet sind (Meter, ohne KBS), in ein Ziel-KBS (Vorgabe "
         "WGS84).\n"
         "Modus 'Ankerpunkt': ANCHOR im Kartenfenster (beliebiges KBS) für den CAD-Punkt CAD_ANCHOR_X/Y "
         "wählen (Vorgabe der Zeichnungsursprung); ROTATION ist die Richtung der +y-Achse des Plans in Grad "
         "im Uhrzeigersinn von Norden, oder ROTATION_POINT (ein zweiter Kartenpunkt) für den CAD-Punkt "
         "CAD_ROTATION_X/Y angeben, dann wird die Drehung aus den zwei gewählten Punkten berechnet; SCALE "
         "ist Meter im Gelände je CAD-Meter.\n"
         "Modus 'Passpunkte': GCPS ist ein Punktlayer, dessen Geometrie jeweils der auf einer "
         "Hintergrundkarte gewählte Punkt ist und dessen Felder cad_x, cad_y (oder sourceX, sourceY) seine "
         "CAD-Koordinaten enthalten; mindestens 2 Punkte, nicht alle auf einer Geraden. Eine "
         "Ähnlichkeitstransformation (Helmert) wird nach kleinsten Quadraten gelöst, und das Residuum jedes "
         "Punktes sowie ihr RMS werden in Metern gemeldet.\n"
         "FIX_SCALE hält SCALE bei der Ausgleichung fest (löst nur Lage und Drehung).\n"
         "AREAS und PASSAGES: Layer im CAD-System (Meter, ohne KBS), z. B. die Ausgaben von „Verfeinern“; "
         "OUTPUT_AREAS und OUTPUT_PASSAGES erhalten sie in TARGET_CRS (Vorgabe WGS84, EPSG:4326) mit allen "
         "Feldern. MODE wählt 'Ankerpunkt + Drehung' oder 'Passpunkte'. CAD_ANCHOR_X / CAD_ANCHOR_Y und "
         "CAD_ROTATION_X / CAD_ROTATION_Y sind CAD-Koordinaten in Metern.\n"
         "Alle Umrechnungen laufen über eine transversale Mercator-Projektion mit dem Anker als Mitte "
         "(pyproj/PROJ), nie über eine Flache-Erde-Näherung. Eine Hintergrundkarte hinzufügen (Vektor ▸ CAD "
         "zu osmAG ▸ … Hintergrundkarte hinzufügen), um Punkte auf echten Luftbildern zu wählen, oder den "
         "Plan mit Vektor ▸ CAD zu osmAG ▸ Einen Grundriss auf der Karte platzieren an seinen Ort ziehen; "
         "diese Platzierung liefert ANCHOR, ROTATION und SCALE.\n"
         "Ausgaben: RMS und RESIDUALS, die Residuen der Passpunkte in Metern (gesamt und je Punkt); FRAME, "
         "die Platzierung als Text; ANCHOR_LON und ANCHOR_LAT (Grad), ROTATION_DEG (Grad im Uhrzeigersinn "
         "von Norden) und SCALE_FACTOR der Platzierung, zur Wiederverwendung für die anderen Geschosse."),
    "Anchor point + rotation": "Ankerpunkt + Drehung",
    "Control points (least squares)": "Passpunkte (kleinste Quadrate)",
    "Layer in the CAD frame (areas or any)": "Layer im CAD-System (Flächen oder beliebig)",
    "Second layer in the CAD frame (passages)": "Zweiter Layer im CAD-System (Durchgänge)",
    "Mode": "Modus",
    "Anchor: where the CAD anchor point lies on the map": "Anker: wo der CAD-Ankerpunkt auf der Karte liegt",
    "CAD anchor point x (m)": "CAD-Ankerpunkt x (m)",
    "CAD anchor point y (m)": "CAD-Ankerpunkt y (m)",
    "Rotation of the plan's +y axis (degrees clockwise from north)":
        "Drehung der +y-Achse des Plans (Grad im Uhrzeigersinn von Norden)",
    "Or: second map point (defines the rotation)": "Oder: zweiter Kartenpunkt (legt die Drehung fest)",
    "CAD x of the second point (m)": "CAD-x des zweiten Punktes (m)",
    "CAD y of the second point (m)": "CAD-y des zweiten Punktes (m)",
    "Scale (ground metres per CAD metre)": "Maßstab (Meter im Gelände je CAD-Meter)",
    "Control points (fields cad_x, cad_y)": "Passpunkte (Felder cad_x, cad_y)",
    "Control points: keep the scale at SCALE (solve rotation and shift only)":
        "Passpunkte: Maßstab auf SCALE festhalten (nur Drehung und Verschiebung lösen)",
    "Target CRS": "Ziel-KBS",
    "Georeferenced layer": "Georeferenzierter Layer",
    "Georeferenced second layer": "Georeferenzierter zweiter Layer",
    "RMS of control point residuals (m)": "RMS der Passpunkt-Residuen (m)",
    "Residual per control point (m)": "Residuum je Passpunkt (m)",
    "Anchor, rotation, scale of the placement": "Anker, Drehung, Maßstab der Platzierung",
    "Anchor longitude": "Längengrad des Ankers",
    "Anchor latitude": "Breitengrad des Ankers",
    "Rotation (deg)": "Drehung (Grad)",
    "Scale": "Maßstab",
    "Mode 'Control points' needs the GCPS point layer": "Modus 'Passpunkte' benötigt den Punktlayer GCPS",
    "GCPS needs fields with the CAD coordinates of each point: cad_x and cad_y (found: {})":
        "GCPS benötigt Felder mit den CAD-Koordinaten jedes Punktes: cad_x und cad_y (gefunden: {})",
    "control point {} has no geometry": "Passpunkt {} hat keine Geometrie",
    "control point {} has no numeric {} / {}": "Passpunkt {} hat kein numerisches {} / {}",
    "GCPS has no CRS: its points must be picked on a map":
        "GCPS hat kein KBS: Seine Punkte müssen auf einer Karte gewählt werden",
    "control point {}: residual {:.4f} m": "Passpunkt {}: Residuum {:.4f} m",
    "RMS of residuals: {:.4f} m ({} points)": "RMS der Residuen: {:.4f} m ({} Punkte)",
    ("The control points do not fit a similarity transform well (RMS {:.2f} m, worst point {} off by {:.2f} "
     "m): check that each point's CAD x/y match where it was picked"):
        ("Die Passpunkte passen schlecht zu einer Ähnlichkeitstransformation (RMS {:.2f} m, schlechtester "
         "Punkt {} um {:.2f} m daneben): prüfen, ob CAD-x/y jedes Punktes zu der Stelle passen, an der er "
         "gewählt wurde"),
    ("The fitted scale is {:.4f} (the plan would be stretched by {:+.1%}): check the drawing units or the "
     "control points, or set FIX_SCALE"):
        ("Der ausgeglichene Maßstab ist {:.4f} (der Plan würde um {:+.1%} gestreckt): die "
         "Zeichnungseinheiten oder die Passpunkte prüfen, oder FIX_SCALE setzen"),
    "Mode 'Anchor' needs ANCHOR: pick the point on the map canvas where the CAD anchor point lies":
        "Modus 'Ankerpunkt' benötigt ANCHOR: im Kartenfenster den Punkt wählen, an dem der CAD-Ankerpunkt liegt",
    "rotation from the two picked points: {:.4f} degrees":
        "Drehung aus den zwei gewählten Punkten: {:.4f} Grad",
    ("{} is already georeferenced ({}); this algorithm places layers in the CAD frame (the outputs of the "
     "segment and refine algorithms). Use 'Reproject layer' to change the CRS of a placed layer."):
        ("{} ist bereits georeferenziert ({}); dieser Algorithmus platziert Layer im CAD-System (die "
         "Ausgaben der Algorithmen Segmentieren und Verfeinern). Mit „Layer reprojizieren“ das KBS eines "
         "platzierten Layers ändern."),
    "{} feature {}: {}": "{} Objekt {}: {}",
    "placement: {}": "Platzierung: {}",
    # --- ListLayersAlgorithm
    "List DXF/DWG layers": "DXF/DWG-Layer auflisten",
    ("Reports every layer of INPUT, a DXF or DWG drawing (DWG: AutoCAD R13-2018, read directly), with its "
     "entity counts by type (after exploding blocks: entities on layer 0 inside a block count on the "
     "INSERT's layer), whether it is frozen or off, and whether the layer rules keep it (kind and matching "
     "keyword; door layers are listed with kind 'door' but not kept, since doorways stay open unless doors "
     "are included). Use the table to choose the LAYERS of 'Extract structure from DXF/DWG' or to write "
     "your own LAYER_RULES JSON file.\n"
     "Layer names as delivered: the rules match the meaningful part of a name (the prefix of a bound "
     "external reference, as in E1-RI-1F$0$A-WALL, is ignored); the 'matched' column shows it.\n"
     "LAYER_RULES: a JSON file of layer keywords (empty: the built-in rules, "
     "algorithms/default_layer_rules.json).\n"
     "Outputs: OUTPUT, a table without geometry, one row per layer (save it as CSV, or keep it as a memory "
     "layer); LAYER_COUNT, the number of layers; KEPT_LAYERS, the layers the rules keep (separated by ';'); "
     "HEADER_UNIT, the unit written in the drawing's header ($INSUNITS)."):
        ("Meldet jeden Layer von INPUT, einer DXF- oder DWG-Zeichnung (DWG: AutoCAD R13-2018, direkt "
         "gelesen), mit seinen Objektanzahlen je Typ (nach dem Auflösen der Blöcke: Objekte auf Layer 0 in "
         "einem Block zählen auf dem Layer des INSERT), ob er gefroren oder ausgeschaltet ist und ob die "
         "Layer-Regeln ihn behalten (Art und passendes Schlüsselwort; Tür-Layer werden mit der Art 'door' "
         "aufgeführt, aber nicht behalten, da Türöffnungen offen bleiben, außer Türen werden einbezogen). "
         "Mit der Tabelle die LAYERS von „Bauteile aus DXF/DWG extrahieren“ wählen oder eine eigene "
         "LAYER_RULES-JSON-Datei schreiben.\n"
         "Layernamen wie geliefert: Die Regeln prüfen den aussagekräftigen Teil eines Namens (das Präfix "
         "einer gebundenen externen Referenz, wie in E1-RI-1F$0$A-WALL, wird ignoriert); die Spalte "
         "'matched' zeigt ihn.\n"
         "LAYER_RULES: eine JSON-Datei mit Layer-Schlüsselwörtern (leer: die eingebauten Regeln, "
         "algorithms/default_layer_rules.json).\n"
         "Ausgaben: OUTPUT, eine Tabelle ohne Geometrie, eine Zeile je Layer (als CSV speichern oder als "
         "temporären Layer behalten); LAYER_COUNT, die Anzahl der Layer; KEPT_LAYERS, die von den Regeln "
         "behaltenen Layer (durch ';' getrennt); HEADER_UNIT, die im Dateikopf der Zeichnung stehende "
         "Einheit ($INSUNITS)."),
    "Layer report": "Layer-Bericht",
    "Number of layers": "Anzahl der Layer",
    "Layers the rules keep (semicolon separated)": "Von den Regeln behaltene Layer (durch Semikolon getrennt)",
    "Unit written in the header ($INSUNITS)": "Im Dateikopf stehende Einheit ($INSUNITS)",
    "{} layers, {} kept by the rules: {}": "{} Layer, {} von den Regeln behalten: {}",
    # --- Cad2OsmagAlgorithm
    "style not stored in {}: {}": "Stil nicht in {} gespeichert: {}",
    "cannot convert to {}: {}": "Umrechnung nach {} nicht möglich: {}",
    "unclosed area ways (skipped): {}": "nicht geschlossene Flächenwege (übersprungen): {}",
    "dangling references (skipped): nodes {} refs {}":
        "verwaiste Verweise (übersprungen): Knoten {} Verweise {}",
    # --- LoadOsmagAlgorithm
    "Load osmAG (.osm)": "osmAG laden (.osm)",
    ("Opens an osmAG file (semantic or fix-id variant; written by this plugin, JOSM or other osmAG tools) "
     "as an areas polygon layer and a passages line layer with every tag as a field (plus osm_id, and "
     "from_id / to_id resolving each passage's areas to their way ids, and vertical = yes for a passage "
     "between two stair or lift areas). Areas are coloured by osmAG:areatype, passages drawn as bold red "
     "lines and vertical passages thick blue (styles/osmag_*.qml), both labelled with their name; "
     "GeoPackage outputs keep the style. Dangling references (missing nodes, passages naming unknown areas) "
     "and unclosed area ways are reported and skipped. A file without any osmAG area is rejected.\n"
     "INPUT: the osmAG file (.osm, OpenStreetMap XML, coordinates in WGS84 degrees).\n"
     "TARGET_CRS: CRS of the output layers (default WGS84, EPSG:4326); choose a projected CRS in metres to "
     "measure or edit the areas.\n"
     "OUTPUT_AREAS / OUTPUT_PASSAGES: the two layers (temporary, GeoPackage, …).\n"
     "Outputs: the number of areas and passages loaded (AREA_COUNT, PASSAGE_COUNT), the unclosed area ways "
     "(UNCLOSED) and dangling references (DANGLING) skipped, the root node's position (ROOT_LON, ROOT_LAT, "
     "degrees) and the VARIANT detected."):
        ("Öffnet eine osmAG-Datei (Variante semantic oder fix-id; geschrieben von diesem Plugin, JOSM oder "
         "anderen osmAG-Werkzeugen) als Polygonlayer der Flächen und Linienlayer der Durchgänge, mit jedem "
         "Tag als Feld (dazu osm_id, sowie from_id / to_id, die die Flächen jedes Durchgangs in ihre "
         "Weg-Kennungen auflösen, und vertical = yes für einen Durchgang zwischen zwei Treppen- oder "
         "Aufzugsflächen). Flächen werden nach osmAG:areatype eingefärbt, Durchgänge als kräftige rote "
         "Linien und vertikale Durchgänge dick blau gezeichnet (styles/osmag_*.qml), beide mit ihrem Namen "
         "beschriftet; GeoPackage-Ausgaben behalten den Stil. Verwaiste Verweise (fehlende Knoten, "
         "Durchgänge, die unbekannte Flächen nennen) und nicht geschlossene Flächenwege werden gemeldet und "
         "übersprungen. Eine Datei ohne jede osmAG-Fläche wird abgelehnt.\n"
         "INPUT: die osmAG-Datei (.osm, OpenStreetMap-XML, Koordinaten in WGS84-Grad).\n"
         "TARGET_CRS: KBS der Ausgabelayer (Vorgabe WGS84, EPSG:4326); ein projiziertes KBS in Metern "
         "wählen, um die Flächen zu messen oder zu bearbeiten.\n"
         "OUTPUT_AREAS / OUTPUT_PASSAGES: die zwei Layer (temporär, GeoPackage, …).\n"
         "Ausgaben: die Anzahl geladener Flächen und Durchgänge (AREA_COUNT, PASSAGE_COUNT), die "
         "übersprungenen nicht geschlossenen Flächenwege (UNCLOSED) und verwaisten Verweise (DANGLING), die "
         "Lage des Wurzelknotens (ROOT_LON, ROOT_LAT, Grad) und die erkannte VARIANT."),
    "Output CRS": "Ausgabe-KBS",
    "osmAG areas": "osmAG-Flächen",
    "osmAG passages": "osmAG-Durchgänge",
    "Areas loaded": "Geladene Flächen",
    "Passages loaded": "Geladene Durchgänge",
    "Unclosed area ways (skipped)": "Nicht geschlossene Flächenwege (übersprungen)",
    "Dangling references (skipped)": "Verwaiste Verweise (übersprungen)",
    "Root node longitude": "Längengrad des Wurzelknotens",
    "Root node latitude": "Breitengrad des Wurzelknotens",
    "Variant detected": "Erkannte Variante",
    # --- MergeFloorsAlgorithm
    "Merge osmAG floors into a building": "osmAG-Geschosse zu einem Gebäude zusammenführen",
    ("Fuses floors into one osmAG building. INPUT: osmAG floor files (semantic or fix-id), and/or "
     "AREAS/PASSAGES layers (e.g. from 'Load osmAG') split by their 'level' field.\n"
     "Level of each floor: LEVELS (comma-separated, in the order of the inputs), else the floor's level "
     "tags, else its file name (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: metres per level (one value "
     "for all, or one per floor; default: the floor's height tag, else 3.2).\n"
     "Registration: floors drawn in different frames are moved onto each other with their stairs and lifts "
     "(areas typed stairs/elevator, or named like one): matched by name first, else by type, size and "
     "position, by consensus (one wrong match does not move a floor); rotation when two anchors agree. The "
     "log gives the residual per anchor and the RMS. Floors without anchors are registered by their "
     "outline, with a warning.\n"
     "Stitching: overlapping stairs/lifts of consecutive levels get a vertical passage (a two-node way "
     "inside both shafts, tagged with the upper level and height). One building structure area is the "
     "parent of one structure area per level, which is the parent of that floor's areas; ids and names are "
     "unique across the building. Passages naming areas that do not exist are reported with their ids and "
     "left out (STRICT: stop instead). REGISTER (on by default): move the floors onto each other as above; "
     "off: keep every floor where it is. BUILDING: the building's name (the root structure area). VARIANT: "
     "the osmAG variant written: as the inputs, semantic (passages name their areas) or fix-id (passages "
     "give way ids).\n"
     "Outputs: OUTPUT, one osmAG file (written atomically); optional OUTPUT_AREAS and OUTPUT_PASSAGES "
     "layers with a 'level' field; FLOOR_COUNT, VERTICAL_PASSAGES, AREA_COUNT and PASSAGE_COUNT (numbers "
     "written), RMS (registration residual in metres), DROPPED_PASSAGES (passages left out) and LEVELS_OUT "
     "(the levels, in order)."):
        ("Fügt Geschosse zu einem osmAG-Gebäude zusammen. INPUT: osmAG-Geschossdateien (semantic oder "
         "fix-id) und/oder AREAS/PASSAGES-Layer (z. B. aus „osmAG laden“), nach ihrem Feld 'level' "
         "aufgeteilt.\n"
         "Geschoss jeder Etage: LEVELS (durch Komma getrennt, in der Reihenfolge der Eingaben), sonst die "
         "level-Tags der Etage, sonst ihr Dateiname (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: Meter je "
         "Geschoss (ein Wert für alle oder einer je Etage; Vorgabe: das height-Tag der Etage, sonst 3.2).\n"
         "Registrierung: Geschosse, die in verschiedenen Systemen gezeichnet sind, werden über ihre Treppen "
         "und Aufzüge aufeinander verschoben (Flächen vom Typ stairs/elevator oder so benannt): zuerst nach "
         "Namen zugeordnet, sonst nach Typ, Größe und Lage, im Konsens (eine falsche Zuordnung verschiebt "
         "kein Geschoss); Drehung, wenn zwei Anker übereinstimmen. Das Protokoll nennt das Residuum je "
         "Anker und den RMS. Geschosse ohne Anker werden über ihren Umriss registriert, mit einer Warnung.\n"
         "Verknüpfung: Überlappende Treppen/Aufzüge aufeinanderfolgender Geschosse erhalten einen "
         "vertikalen Durchgang (ein Weg mit zwei Knoten in beiden Schächten, mit dem oberen Geschoss und "
         "der Höhe getaggt). Eine Gebäude-Strukturfläche ist die Elternfläche je einer Strukturfläche pro "
         "Geschoss, die wiederum die Elternfläche der Flächen dieses Geschosses ist; Kennungen und Namen "
         "sind im ganzen Gebäude eindeutig. Durchgänge, die nicht vorhandene Flächen nennen, werden mit "
         "ihren Kennungen gemeldet und weggelassen (STRICT: stattdessen abbrechen). REGISTER (als Vorgabe "
         "an): die Geschosse wie oben aufeinander verschieben; aus: jedes Geschoss bleibt, wo es ist. "
         "BUILDING: der Name des Gebäudes (die oberste Strukturfläche). VARIANT: die geschriebene "
         "osmAG-Variante: wie die Eingaben, semantic (Durchgänge nennen ihre Flächen beim Namen) oder "
         "fix-id (Durchgänge geben Weg-Kennungen an).\n"
         "Ausgaben: OUTPUT, eine osmAG-Datei (atomar geschrieben); optionale Layer OUTPUT_AREAS und "
         "OUTPUT_PASSAGES mit einem Feld 'level'; FLOOR_COUNT, VERTICAL_PASSAGES, AREA_COUNT und "
         "PASSAGE_COUNT (geschriebene Anzahlen), RMS (Registrierungsresiduum in Metern), DROPPED_PASSAGES "
         "(weggelassene Durchgänge) und LEVELS_OUT (die Geschosse, der Reihe nach)."),
    "osmAG floor files": "osmAG-Geschossdateien",
    "Areas layer (several floors, 'level' field)": "Flächenlayer (mehrere Geschosse, Feld 'level')",
    "Passages layer": "Durchgangslayer",
    "Levels, one per floor file (empty: level tags, else file names)":
        "Geschosse, eines je Geschossdatei (leer: level-Tags, sonst Dateinamen)",
    "Height per level in metres (one value, or one per floor)":
        "Höhe je Geschoss in Metern (ein Wert oder einer je Geschoss)",
    "Building name": "Gebäudename",
    "Register the floors on their stairs/lifts (off: keep them where they are)":
        "Die Geschosse über ihre Treppen/Aufzüge registrieren (aus: sie bleiben, wo sie sind)",
    "Stop on passages whose areas are missing (off: report and leave them out)":
        "Bei Durchgängen mit fehlenden Flächen abbrechen (aus: melden und weglassen)",
    "Building osmAG file": "osmAG-Datei des Gebäudes",
    "Building areas": "Flächen des Gebäudes",
    "Building passages": "Durchgänge des Gebäudes",
    "Floors": "Geschosse",
    "Vertical passages": "Vertikale Durchgänge",
    "Registration residual RMS (m)": "RMS des Registrierungsresiduums (m)",
    "Passages left out": "Weggelassene Durchgänge",
    "Levels": "Geschosse",
    "INPUT: give at least one osmAG floor file (or an AREAS layer)":
        "INPUT: mindestens eine osmAG-Geschossdatei angeben (oder einen AREAS-Layer)",
    "HEIGHTS must be numbers (metres), e.g. 3.2 or 4.5,3.2,3.2":
        "HEIGHTS müssen Zahlen sein (Meter), z. B. 3.2 oder 4.5,3.2,3.2",
    "floor file '{}' does not exist": "Geschossdatei '{}' existiert nicht",
    "AREAS has no CRS (CAD frame): georeference it first (cad2osmag:georeference)":
        "AREAS hat kein KBS (CAD-System): zuerst georeferenzieren (cad2osmag:georeference)",
    "LEVELS gives {} levels for {} floors; give one per floor, in the order of the inputs":
        "LEVELS nennt {} Geschosse für {} Etagen; eines je Etage angeben, in der Reihenfolge der Eingaben",
    "level {}: shift ({:.3f}, {:.3f}) m, rotation {:.3f}°, {}":
        "Geschoss {}: Verschiebung ({:.3f}, {:.3f}) m, Drehung {:.3f}°, {}",
    # --- RasterizeAlgorithm
    "Rasterize structure": "Bauteile rastern",
    ("Turns structure lines (the WALLS output of 'Extract structure from DXF/DWG', or any line/polygon "
     "layer in metres) into a single-band occupancy GeoTIFF: 0 = free, 255 = occupied (the inverse of a ROS "
     "map_server image, where black is occupied). Hairlines are drawn 0.15 m wide, wide polylines with "
     "their width, filled outlines (solid hatches) filled.\n"
     "The extent is the PERCENTILES (low, high) of all vertices grown to the entities that reach into them, "
     "plus PADDING (a fraction of the building size), so stray entities far away do not blow up the raster. "
     "The origin is snapped to a multiple of RESOLUTION and the geotransform maps pixels back to the "
     "drawing frame exactly.\n"
     "Repair: a closing with a KERNEL x KERNEL square bridges gaps up to about 0.2 m, then an opening "
     "removes isolated specks (components that do not survive the opening and are small). STROKE: the width "
     "in metres hairlines are drawn with (0.15 m).\n"
     "Multi-floor sets: give the structure layers of all floors as FLOOR_LAYERS (and/or a COMMON_EXTENT in "
     "the first floor's frame); every floor rasterized with the same values gets the same grid, pixel for "
     "pixel. Floors drawn with different origins (their extents do not overlap) are registered by "
     "cross-correlation (ALIGN_FLOORS); each raster's geotransform still maps its pixels onto its own "
     "drawing frame, so the origins differ by the floor offset but the pixels line up.\n"
     "A raster above MAX_MPX megapixels stops with an error that suggests a resolution.\n"
     "STAIRS_AS_OBSTACLES: draw stair and lift symbols as walls (off by default: stairs and lifts stay free "
     "space, so they become areas). DOORS (optional): doorway lines (jamb to jamb, the DOORS output of "
     "'Extract structure') kept open even where a door layer is drawn.\n"
     "Outputs: OCCUPANCY, the GeoTIFF (in the drawing frame, metres); WIDTH and HEIGHT in pixels; "
     "OCCUPIED_SHARE, the share of occupied pixels (0-1)."):
        ("Wandelt Bauteillinien (die WALLS-Ausgabe von „Bauteile aus DXF/DWG extrahieren“ oder einen "
         "beliebigen Linien-/Polygonlayer in Metern) in ein einkanaliges Belegungs-GeoTIFF um: 0 = frei, "
         "255 = belegt (die Umkehrung eines ROS-map_server-Bildes, in dem Schwarz belegt ist). Haarlinien "
         "werden 0.15 m breit gezeichnet, breite Polylinien mit ihrer Breite, gefüllte Umrisse "
         "(Volltonschraffuren) gefüllt.\n"
         "Die Ausdehnung sind die PERCENTILES (unteres, oberes) aller Stützpunkte, erweitert um die "
         "Objekte, die in sie hineinreichen, plus PADDING (ein Anteil der Gebäudegröße), damit vereinzelte "
         "weit entfernte Objekte das Raster nicht aufblähen. Der Ursprung wird auf ein Vielfaches von "
         "RESOLUTION gerundet, und die Geotransformation bildet die Pixel exakt auf das System der "
         "Zeichnung ab.\n"
         "Reparatur: Ein Schließen mit einem Quadrat von KERNEL x KERNEL überbrückt Lücken bis etwa 0.2 m, "
         "danach entfernt ein Öffnen vereinzelte Sprenkel (Komponenten, die das Öffnen nicht überstehen und "
         "klein sind). STROKE: die Breite in Metern, mit der Haarlinien gezeichnet werden (0.15 m).\n"
         "Mehrgeschossige Sätze: die Bauteil-Layer aller Geschosse als FLOOR_LAYERS angeben (und/oder eine "
         "COMMON_EXTENT im System des ersten Geschosses); jedes mit denselben Werten gerasterte Geschoss "
         "erhält dasselbe Raster, Pixel für Pixel. Geschosse mit verschiedenen Ursprüngen (ihre "
         "Ausdehnungen überlappen nicht) werden per Kreuzkorrelation registriert (ALIGN_FLOORS); die "
         "Geotransformation jedes Rasters bildet seine Pixel weiterhin auf das eigene System der Zeichnung "
         "ab, die Ursprünge unterscheiden sich also um den Geschossversatz, aber die Pixel liegen "
         "deckungsgleich.\n"
         "Ein Raster über MAX_MPX Megapixel bricht mit einer Fehlermeldung ab, die eine Auflösung "
         "vorschlägt.\n"
         "STAIRS_AS_OBSTACLES: Treppen- und Aufzugssymbole als Wände zeichnen (als Vorgabe aus: Treppen und "
         "Aufzüge bleiben freier Raum und werden so zu Flächen). DOORS (optional): Türöffnungslinien (von "
         "Laibung zu Laibung, die DOORS-Ausgabe von „Bauteile extrahieren“), die offen bleiben, auch wo ein "
         "Tür-Layer gezeichnet ist.\n"
         "Ausgaben: OCCUPANCY, das GeoTIFF (im System der Zeichnung, Meter); WIDTH und HEIGHT in Pixeln; "
         "OCCUPIED_SHARE, der Anteil belegter Pixel (0-1)."),
    "Resolution (m/pixel)": "Auflösung (m/Pixel)",
    "Padding (fraction of the building size)": "Rand (Anteil der Gebäudegröße)",
    "Vertex percentiles for the extent (low, high)":
        "Stützpunkt-Perzentile für die Ausdehnung (unteres, oberes)",
    "Repair kernel (pixels, 0 = no repair)": "Reparaturkern (Pixel, 0 = keine Reparatur)",
    "Width of hairlines (m)": "Breite von Haarlinien (m)",
    "Pixel budget (megapixels)": "Pixelbudget (Megapixel)",
    "Common extent for multi-floor sets (optional)":
        "Gemeinsame Ausdehnung für mehrgeschossige Sätze (optional)",
    "Structure layers of all floors: rasterize on their common extent (optional)":
        "Bauteil-Layer aller Geschosse: auf ihrer gemeinsamen Ausdehnung rastern (optional)",
    "Register the floors (translation) before building the common grid":
        "Die Geschosse (Verschiebung) registrieren, bevor das gemeinsame Raster gebildet wird",
    "automatic (only when the floors do not overlap)": "automatisch (nur wenn die Geschosse nicht überlappen)",
    "yes": "ja",
    "no": "nein",
    "Draw stair and lift symbols as obstacles": "Treppen- und Aufzugssymbole als Hindernisse zeichnen",
    "Doorways (jamb-to-jamb lines) kept open (optional)":
        "Offen gehaltene Türöffnungen (Linien von Laibung zu Laibung, optional)",
    "Occupancy raster": "Belegungsraster",
    "Raster width (pixels)": "Rasterbreite (Pixel)",
    "Raster height (pixels)": "Rasterhöhe (Pixel)",
    "Share of occupied pixels": "Anteil belegter Pixel",
    "The structure layer (WALLS) could not be loaded.":
        "Der Bauteil-Layer (WALLS) konnte nicht geladen werden.",
    "PERCENTILES must be two numbers such as '0.5, 99.5', got '{}'":
        "PERCENTILES müssen zwei Zahlen wie '0.5, 99.5' sein, erhalten: '{}'",
    ("The structure layer is in a geographic CRS ({}); rasterize needs metres: use the WALLS output of "
     "'Extract structure from DXF/DWG' or reproject to a projected CRS first."):
        ("Der Bauteil-Layer liegt in einem geographischen KBS ({}); das Rastern braucht Meter: die "
         "WALLS-Ausgabe von „Bauteile aus DXF/DWG extrahieren“ verwenden oder zuerst in ein projiziertes "
         "KBS umprojizieren."),
    "This floor is offset by ({:.3f}, {:.3f}) m from the first floor layer":
        "Dieses Geschoss ist um ({:.3f}, {:.3f}) m gegen den Layer des ersten Geschosses versetzt",
    "Cannot write the raster '{}': {}": "Das Raster '{}' kann nicht geschrieben werden: {}",
    "{} x {} px at {} m/px, origin ({:.3f}, {:.3f}), {:.1%} occupied":
        "{} x {} px bei {} m/px, Ursprung ({:.3f}, {:.3f}), {:.1%} belegt",
    # --- Cad2OsmagAlgorithm
    "{}: features with ids {} have empty or missing geometries; remove them or fix the layer":
        ("{}: Die Objekte mit den Kennungen {} haben leere oder fehlende Geometrien; sie entfernen oder den "
         "Layer reparieren"),
    "PASSAGES: passage {} has no valid {} (value {!r}); it must name the id of an area":
        "PASSAGES: Durchgang {} hat kein gültiges {} (Wert {!r}); es muss die Kennung einer Fläche nennen",
    "PASSAGES: passage {} has no line geometry": "PASSAGES: Durchgang {} hat keine Liniengeometrie",
    "cannot write passage {} to the output layer":
        "Durchgang {} kann nicht in den Ausgabelayer geschrieben werden",
    # --- RefineAlgorithm
    "Refine areas (simplify, remove spikes, merge small areas)":
        "Flächen verfeinern (vereinfachen, Spitzen entfernen, kleine Flächen zusammenführen)",
    ("Makes the segmented areas light and clean while adjacent areas keep identical vertices along their "
     "shared borders. Every border between two junctions is simplified once with Douglas-Peucker (tolerance "
     "EPSILON_PX x RESOLUTION, the reported physical bound), spikes (angle below SPIKE_ANGLE, protrusion "
     "below SPIKE_LENGTH) are removed iteratively, and passage end points are locked, so each passage stays "
     "a segment whose two ends are vertices of both areas it joins. Areas smaller than MIN_AREA are merged "
     "into the neighbour they share the longest border with (stairs and elevators are kept); isolated ones "
     "are dropped. Work in metres: run it on the CAD frame (before georeferencing) or on a projected CRS.\n"
     "AREAS and PASSAGES: the outputs of 'Segment' (PASSAGES optional). RESOLUTION: the raster resolution "
     "the areas were traced at, in metres per pixel. EPSILON_PX in pixels, SPIKE_ANGLE in degrees, "
     "SPIKE_LENGTH in metres, MIN_AREA in m².\n"
     "Outputs: OUTPUT_AREAS and OUTPUT_PASSAGES, the refined layers; VERTICES_BEFORE, VERTICES_AFTER and "
     "VERTEX_REDUCTION (%); MAX_DEVIATION, the largest distance from the unsimplified areas (m); EPSILON_M, "
     "the tolerance in metres; AREA_COUNT and PASSAGE_COUNT written; MERGED and DROPPED small areas; "
     "COMPONENTS, the connected parts of the area graph, and LARGEST_COMPONENT_SHARE, the share of the area "
     "in the largest one."):
        ("Macht die segmentierten Flächen schlank und sauber, wobei benachbarte Flächen entlang ihrer "
         "gemeinsamen Kanten identische Stützpunkte behalten. Jede Kante zwischen zwei Knotenpunkten wird "
         "einmal mit Douglas-Peucker vereinfacht (Toleranz EPSILON_PX x RESOLUTION, die gemeldete "
         "physikalische Schranke), Spitzen (Winkel unter SPIKE_ANGLE, Überstand unter SPIKE_LENGTH) werden "
         "wiederholt entfernt, und die Endpunkte der Durchgänge sind fixiert, sodass jeder Durchgang eine "
         "Strecke bleibt, deren beide Enden Stützpunkte beider verbundenen Flächen sind. Flächen kleiner "
         "als MIN_AREA werden mit der Nachbarfläche zusammengeführt, mit der sie die längste Kante teilen "
         "(Treppen und Aufzüge bleiben erhalten); isolierte werden verworfen. In Metern arbeiten: im "
         "CAD-System (vor dem Georeferenzieren) oder in einem projizierten KBS ausführen.\n"
         "AREAS und PASSAGES: die Ausgaben von „Segmentieren“ (PASSAGES optional). RESOLUTION: die "
         "Rasterauflösung, mit der die Flächen nachgezeichnet wurden, in Metern je Pixel. EPSILON_PX in "
         "Pixeln, SPIKE_ANGLE in Grad, SPIKE_LENGTH in Metern, MIN_AREA in m².\n"
         "Ausgaben: OUTPUT_AREAS und OUTPUT_PASSAGES, die verfeinerten Layer; VERTICES_BEFORE, "
         "VERTICES_AFTER und VERTEX_REDUCTION (%); MAX_DEVIATION, der größte Abstand zu den unvereinfachten "
         "Flächen (m); EPSILON_M, die Toleranz in Metern; AREA_COUNT und PASSAGE_COUNT geschrieben; MERGED "
         "und DROPPED, zusammengeführte und verworfene kleine Flächen; COMPONENTS, die zusammenhängenden "
         "Teile des Flächengraphen, und LARGEST_COMPONENT_SHARE, der Flächenanteil im größten davon."),
    "Raster resolution r the areas were traced at (m/px)":
        "Rasterauflösung r, mit der die Flächen nachgezeichnet wurden (m/px)",
    "Douglas-Peucker tolerance ε (pixels)": "Douglas-Peucker-Toleranz ε (Pixel)",
    "Spike angle below (degrees)": "Spitzenwinkel unter (Grad)",
    "Spike protrusion below (m)": "Spitzenüberstand unter (m)",
    "Refined areas": "Verfeinerte Flächen",
    "Refined passages": "Verfeinerte Durchgänge",
    "Vertices before": "Stützpunkte vorher",
    "Vertices after": "Stützpunkte nachher",
    "Vertex reduction (%)": "Verringerung der Stützpunkte (%)",
    "Maximum deviation from the unsimplified areas (m)":
        "Größte Abweichung von den unvereinfachten Flächen (m)",
    "Tolerance ε·r (m)": "Toleranz ε·r (m)",
    "Small areas merged": "Zusammengeführte kleine Flächen",
    "Isolated small areas dropped": "Verworfene isolierte kleine Flächen",
    "Connected components of the area graph": "Zusammenhangskomponenten des Flächengraphen",
    "Share of the area in the largest component": "Flächenanteil in der größten Komponente",
    ("AREAS is in a geographic CRS ({}); refinement works in metres: run it on the CAD frame (before "
     "georeferencing) or reproject to a projected CRS first"):
        ("AREAS liegt in einem geographischen KBS ({}); die Verfeinerung arbeitet in Metern: im CAD-System "
         "ausführen (vor dem Georeferenzieren) oder zuerst in ein projiziertes KBS umprojizieren"),
    # --- RouteAlgorithm
    "Plan a route on an osmAG map": "Eine Route auf einer osmAG-Karte planen",
    ("Shortest route for a round robot of radius ROBOT_RADIUS (metres) over an osmAG map: INPUT, an osmAG "
     "file (ours or any other tool's, semantic or fix-id) or AREAS/PASSAGES layers (e.g. from loadosmag or "
     "refine). START and END are points picked on the canvas (any CRS) with their level "
     "(START_LEVEL/END_LEVEL, needed when floors overlap), or area names (START_NAME/END_NAME). A point up "
     "to 1 m outside the robot's free space is moved into it; farther away is an error. Passages narrower "
     "than twice the radius are closed; inside every area the route is the shortest collision-free path "
     "around its walls. Vertical passages (stairs, lifts) cost VERTICAL_COST metres per level; AVOID leaves "
     "out stairs (lifts only) or lifts and keeps the robot its radius away from them: their doorways are "
     "walls for it (a START or END inside such an area still leaves through its door). The result is a 3-D line (z = level x height) with its length, "
     "cost, levels per vertex and the areas and passages crossed. When no route exists the message names "
     "the separate parts of the map the start and the goal lie in, and the passages too narrow for the "
     "robot.\n"
     "Outputs: OUTPUT, the route line; LENGTH (m) and COST (length + vertical cost, m); LEVEL_CHANGES; "
     "START_SNAP and END_SNAP, how far the start and end were moved (m); QUERY_MS, the search time in "
     "milliseconds; AREAS_CROSSED, PASSAGES_CROSSED and LEVELS (the level of every vertex)."):
        ("Kürzeste Route für einen runden Roboter mit dem Radius ROBOT_RADIUS (Meter) über eine "
         "osmAG-Karte: INPUT, eine osmAG-Datei (von uns oder einem anderen Werkzeug, semantic oder fix-id) "
         "oder AREAS/PASSAGES-Layer (z. B. aus loadosmag oder refine). START und END sind im Kartenfenster "
         "gewählte Punkte (beliebiges KBS) mit ihrem Geschoss (START_LEVEL/END_LEVEL, nötig, wenn Geschosse "
         "übereinander liegen), oder Flächennamen (START_NAME/END_NAME). Ein Punkt bis 1 m außerhalb des "
         "freien Raums des Roboters wird hineingeschoben; weiter entfernt ist ein Fehler. Durchgänge "
         "schmaler als der doppelte Radius sind gesperrt; innerhalb jeder Fläche ist die Route der kürzeste "
         "kollisionsfreie Weg um ihre Wände. Vertikale Durchgänge (Treppen, Aufzüge) kosten VERTICAL_COST "
         "Meter je Geschoss; AVOID lässt Treppen (nur Aufzüge) oder Aufzüge aus und hält den Roboter um seinen Radius "
         "von ihnen fern: ihre Türöffnungen sind für ihn Wände (ein START oder END in einer solchen Fläche "
         "verlässt sie trotzdem durch ihre Tür). Das Ergebnis ist eine "
         "3-D-Linie (z = Geschoss x Höhe) mit Länge, Kosten, Geschoss je Stützpunkt und den durchquerten "
         "Flächen und Durchgängen. Gibt es keine Route, nennt die Meldung die getrennten Teile der Karte, "
         "in denen Start und Ziel liegen, und die für den Roboter zu schmalen Durchgänge.\n"
         "Ausgaben: OUTPUT, die Routenlinie; LENGTH (m) und COST (Länge + vertikale Kosten, m); "
         "LEVEL_CHANGES; START_SNAP und END_SNAP, wie weit Start und Ziel verschoben wurden (m); QUERY_MS, "
         "die Suchzeit in Millisekunden; AREAS_CROSSED, PASSAGES_CROSSED und LEVELS (das Geschoss jedes "
         "Stützpunkts)."),
    "osmAG file (or give AREAS and PASSAGES)": "osmAG-Datei (oder AREAS und PASSAGES angeben)",
    "Areas layer (instead of the file)": "Flächenlayer (statt der Datei)",
    "Start point": "Startpunkt",
    "Start level": "Startgeschoss",
    "Start area name (instead of a point)": "Name der Startfläche (statt eines Punktes)",
    "End point": "Zielpunkt",
    "End level": "Zielgeschoss",
    "End area name (instead of a point)": "Name der Zielfläche (statt eines Punktes)",
    "Robot radius (m)": "Roboterradius (m)",
    "Avoid": "Meiden",
    "Cost of one level of stairs or lift (m)": "Kosten eines Geschosses Treppe oder Aufzug (m)",
    "Route": "Route",
    "Route length (m)": "Routenlänge (m)",
    "Route cost (length + vertical cost)": "Routenkosten (Länge + vertikale Kosten)",
    "Level changes": "Geschosswechsel",
    "Start moved by (m)": "Start verschoben um (m)",
    "End moved by (m)": "Ziel verschoben um (m)",
    "Search time (ms)": "Suchzeit (ms)",
    "Areas crossed": "Durchquerte Flächen",
    "Passages crossed": "Durchquerte Durchgänge",
    "Level of every vertex": "Geschoss jedes Stützpunkts",
    "give an osmAG file (INPUT) or an AREAS layer (with PASSAGES)":
        "eine osmAG-Datei (INPUT) oder einen AREAS-Layer (mit PASSAGES) angeben",
    "PASSAGES is in {} but AREAS is in {}; reproject it first":
        "PASSAGES liegt in {}, AREAS aber in {}; zuerst umprojizieren",
    "{}: give a point or an area name ({})": "{}: einen Punkt oder einen Flächennamen angeben ({})",
    "route: {:.2f} m ({} level changes) through {}": "Route: {:.2f} m ({} Geschosswechsel) über {}",
    "nothing": "nichts",
    "stairs (wheelchairs, wheeled robots: lifts only)": "Treppen (Rollstühle, Roboter auf Rädern: nur Aufzüge)",
    "lifts (evacuation: stairs only)": "Aufzüge (Evakuierung: nur Treppen)",
    # --- SampleBuildingAlgorithm
    "Generate sample building (DXF)": "Beispielgebäude erzeugen (DXF)",
    ("Writes a realistic multi-floor office building as DXF files (millimetres, NCS layers, walls with real "
     "thickness, doors as blocks, glazing, a stair core and a lift, room names as TEXT, MTEXT and ATTRIB, "
     "nested blocks on layer 0, furniture and dimensions) together with a ground-truth GeoJSON per floor "
     "(rooms, doors, stair/lift anchors, in metres). The same seed always gives byte-identical files. Use "
     "it to try the pipeline or to score it.\n"
     "FLOORS: number of floors (1-20), one DXF and one ground-truth file each; all floors share the stair "
     "core and the lift, so they stack.\n"
     "SEED: any whole number; it varies the room layout (0 is the layout the README shows).\n"
     "PREFIX: start of the file names: PREFIX-F1.dxf, PREFIX-F1.gt.geojson, …\n"
     "OUTPUT_FOLDER: where the files are written (created when missing).\n"
     "Outputs: FIRST_FLOOR_DXF (the first floor's DXF), DXF_FILES (every DXF, ';' separated), "
     "GROUND_TRUTH_FILES (the ground-truth GeoJSON files, ';' separated) and FLOOR_COUNT (floors written)."):
        ("Schreibt ein realistisches mehrgeschossiges Bürogebäude als DXF-Dateien (Millimeter, NCS-Layer, "
         "Wände mit echter Dicke, Türen als Blöcke, Verglasung, ein Treppenhauskern und ein Aufzug, "
         "Raumnamen als TEXT, MTEXT und ATTRIB, verschachtelte Blöcke auf Layer 0, Möbel und Bemaßungen) "
         "zusammen mit einer Referenz-GeoJSON je Geschoss (Räume, Türen, Treppen-/Aufzugsanker, in Metern). "
         "Derselbe Startwert ergibt immer byte-identische Dateien. Damit die Verarbeitungskette "
         "ausprobieren oder bewerten.\n"
         "FLOORS: Anzahl der Geschosse (1-20), je eine DXF- und eine Referenzdatei; alle Geschosse teilen "
         "Treppenhauskern und Aufzug, liegen also übereinander.\n"
         "SEED: eine beliebige ganze Zahl; sie variiert die Raumaufteilung (0 ist die Aufteilung, die das "
         "README zeigt).\n"
         "PREFIX: Anfang der Dateinamen: PREFIX-F1.dxf, PREFIX-F1.gt.geojson, …\n"
         "OUTPUT_FOLDER: wohin die Dateien geschrieben werden (wird angelegt, falls nötig).\n"
         "Ausgaben: FIRST_FLOOR_DXF (die DXF des ersten Geschosses), DXF_FILES (jede DXF, durch ';' "
         "getrennt), GROUND_TRUTH_FILES (die Referenz-GeoJSON-Dateien, durch ';' getrennt) und FLOOR_COUNT "
         "(geschriebene Geschosse)."),
    "Number of floors": "Anzahl der Geschosse",
    "Random seed (layout variations)": "Zufallsstartwert (Varianten der Aufteilung)",
    "File name prefix": "Präfix der Dateinamen",
    "DXF of the first floor": "DXF des ersten Geschosses",
    "All DXF files (semicolon separated)": "Alle DXF-Dateien (durch Semikolon getrennt)",
    "Ground-truth GeoJSON files (semicolon separated)": "Referenz-GeoJSON-Dateien (durch Semikolon getrennt)",
    "Number of floors written": "Anzahl geschriebener Geschosse",
    "Wrote {}": "{} geschrieben",
    # --- SegmentAlgorithm
    "Segment occupancy grid into an Area Graph": "Belegungsraster in einen Area Graph segmentieren",
    ("Area Graph segmentation (Hou et al. 2019) with the dynamic alpha of the CAD-to-osmAG method. INPUT is "
     "the output of 'Rasterize', or any occupancy grid: a GeoTIFF, a PNG/PGM image with RESOLUTION (m/px), "
     "or a ROS map.yaml (its resolution, origin, negate and thresholds are used; unknown cells are never "
     "free). Only the free space inside the building envelope is segmented: facade openings narrower than "
     "ENVELOPE_GAP are bridged, outside space is never an area; the log reports the interior area. alpha = "
     "ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 is the probe disk: spaces it sweeps "
     "through an opening are one room; door-sized narrowings that are clearly narrower than the space "
     "behind them separate rooms (this also finds rooms too narrow for the disk); corridor cells merge "
     "where nothing justifies a split; the free space is thinned to its skeleton (generalised Voronoi "
     "diagram), dead-end branches shorter than PRUNE are removed, and every skeleton edge (split at the "
     "narrowings) starts as one region. Outputs: AREAS (exact pixel-edge polygons: id, type room/corridor, "
     "area, perimeter, max clearance), PASSAGES (a segment across every opening between two areas, ends on "
     "the walls: from, to, width), LABELS (area ids on the input grid, 0 outside areas) and, when asked "
     "for, SKELETON (one line per skeleton edge: id, length, min and max clearance). Space open to the "
     "outside is still inside where there is evidence: the plan's footprint (openings up to 3 x "
     "ENVELOPE_GAP, closed at the chord between the facade wall ends, where it opens onto the interior "
     "through a doorway) and the optional TEXTS (room names, from 'Extract structure': the space holding "
     "one is never outside). FOOTPRINT: by default the footprint is used for rasters made by 'Rasterize' "
     "(CAD plans), not for images and ROS maps (robot maps, whose free space beside the rooms is where the "
     "scan ended). The optional DOORS (jamb-to-jamb lines) are kept open and become passages where the "
     "segmentation missed them. Every area has a 'component' field: its connected component in the area "
     "graph (0 = the largest); the log lists the others (rooms no passage reaches). STRUCTURE (optional): "
     "the structure lines of the drawing (WALLS of 'Extract structure'); stair and lift symbols in them "
     "type their areas stairs/elevator. TOPOLOGY_CELL (0.088 m): the skeleton, regions and merges work on cells of about this size (the largest whole multiple of the raster's cell not above it; a cell is free only when all its pixels are, so walls never open), the outlines and passages are traced on the raster's own cells; 0 = everything on the raster's cells (about twice as slow on a 0.044 m CAD raster).\n"
     "Figures: AREA_COUNT, ROOM_COUNT, CORRIDOR_COUNT, PASSAGE_COUNT; INTERIOR_AREA_M2, the free area "
     "inside the building (m²); COMPONENTS and LARGEST_COMPONENT_SHARE (share of the area in the largest "
     "component); ALPHA, the probe disk in px²; SECONDS, the segmentation time."):
        ("Area-Graph-Segmentierung (Hou et al. 2019) mit dem dynamischen Alpha der CAD-to-osmAG-Methode. "
         "INPUT ist die Ausgabe von „Rastern“ oder ein beliebiges Belegungsraster: ein GeoTIFF, ein "
         "PNG/PGM-Bild mit RESOLUTION (m/px) oder eine ROS-map.yaml (deren resolution, origin, negate und "
         "Schwellwerte verwendet werden; unbekannte Zellen sind nie frei). Nur der freie Raum innerhalb der "
         "Gebäudehülle wird segmentiert: Fassadenöffnungen schmaler als ENVELOPE_GAP werden überbrückt, der "
         "Außenraum ist nie eine Fläche; das Protokoll meldet die Innenfläche. alpha = "
         "ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 ist die Prüfscheibe: Räume, die "
         "sie durch eine Öffnung hindurch überstreicht, sind ein Raum; türgroße Engstellen, die deutlich "
         "schmaler sind als der Raum dahinter, trennen Räume (so werden auch Räume gefunden, die für die "
         "Scheibe zu schmal sind); Flurzellen werden zusammengeführt, wo nichts eine Teilung rechtfertigt; "
         "der freie Raum wird zu seinem Skelett verdünnt (verallgemeinertes Voronoi-Diagramm), "
         "Sackgassen-Äste kürzer als PRUNE werden entfernt, und jede Skelettkante (an den Engstellen "
         "geteilt) beginnt als eine Region. Ausgaben: AREAS (exakte Polygone entlang der Pixelkanten: id, "
         "type room/corridor, area, perimeter, größter Freiraum), PASSAGES (eine Strecke quer durch jede "
         "Öffnung zwischen zwei Flächen, mit den Enden an den Wänden: from, to, width), LABELS "
         "(Flächenkennungen auf dem Eingaberaster, 0 außerhalb der Flächen) und, falls gewünscht, SKELETON "
         "(eine Linie je Skelettkante: id, Länge, kleinster und größter Freiraum). Zum Außenraum offener "
         "Raum gilt trotzdem als innen, wo es Belege gibt: die Grundfläche des Plans (Öffnungen bis 3 x "
         "ENVELOPE_GAP, geschlossen an der Sehne zwischen den Enden der Fassadenwände, wo sie sich über "
         "eine Türöffnung zum Inneren öffnet) und die optionalen TEXTS (Raumnamen aus „Bauteile "
         "extrahieren“: Der Raum, der einen enthält, ist nie außen). FOOTPRINT: als Vorgabe wird die "
         "Grundfläche für von „Rastern“ erzeugte Raster (CAD-Pläne) verwendet, nicht für Bilder und "
         "ROS-Karten (Roboterkarten, deren freier Raum neben den Räumen dort ist, wo der Scan endete). Die "
         "optionalen DOORS (Linien von Laibung zu Laibung) bleiben offen und werden zu Durchgängen, wo die "
         "Segmentierung sie verfehlt hat. Jede Fläche hat ein Feld 'component': ihre "
         "Zusammenhangskomponente im Flächengraphen (0 = die größte); das Protokoll listet die übrigen "
         "(Räume, die kein Durchgang erreicht). STRUCTURE (optional): die Bauteillinien der Zeichnung "
         "(WALLS von „Bauteile extrahieren“); Treppen- und Aufzugssymbole darin geben ihren Flächen den Typ "
         "stairs/elevator. TOPOLOGY_CELL (0.088 m): Skelett, Regionen und Zusammenführungen arbeiten auf Zellen etwa dieser Größe (das größte ganze Vielfache der Rasterzelle, das sie nicht übersteigt; eine Zelle ist nur frei, wenn alle ihre Pixel es sind, Wände öffnen sich also nie), Umrisse und Durchgänge werden auf den Pixeln des Rasters selbst nachgezeichnet; 0 = alles auf den Pixeln des Rasters (auf einem CAD-Raster mit 0.044 m etwa doppelt so langsam).\n"
         "Kennzahlen: AREA_COUNT, ROOM_COUNT, CORRIDOR_COUNT, PASSAGE_COUNT; INTERIOR_AREA_M2, die freie "
         "Fläche im Gebäude (m²); COMPONENTS und LARGEST_COMPONENT_SHARE (Flächenanteil in der größten "
         "Komponente); ALPHA, die Prüfscheibe in px²; SECONDS, die Dauer der Segmentierung."),
    "Occupancy grid (GeoTIFF, PNG/PGM, or ROS map.yaml)":
        "Belegungsraster (GeoTIFF, PNG/PGM oder ROS-map.yaml)",
    "Resolution of a plain image (m/px; 0 = from the raster)":
        "Auflösung eines einfachen Bildes (m/px; 0 = aus dem Raster)",
    "Narrowest corridor (m)": "Schmalster Flur (m)",
    "Delta δ added to the width (m)": "Zuschlag δ zur Breite (m)",
    "Prune Voronoi branches shorter than (m)": "Voronoi-Äste kürzer als (m) entfernen",
    "Bridge facade openings up to (m)": "Fassadenöffnungen überbrücken bis (m)",
    "Cell size of the skeleton and merges (m; 0 = the raster's cells)": "Zellgröße von Skelett und Zusammenführungen (m; 0 = die Zellen des Rasters)",
    "Structure lines of the drawing (WALLS of 'Extract structure'), to recognise stairs and lifts":
        "Bauteillinien der Zeichnung (WALLS von „Bauteile extrahieren“), um Treppen und Aufzüge zu erkennen",
    "Use the plan's footprint as evidence of inside space":
        "Die Grundfläche des Plans als Beleg für Innenraum verwenden",
    "automatic (CAD rasters from 'Rasterize': yes; images and ROS maps: no)":
        "automatisch (CAD-Raster aus „Rastern“: ja; Bilder und ROS-Karten: nein)",
    "Room names (TEXTS of 'Extract structure'): evidence of inside space":
        "Raumnamen (TEXTS von „Bauteile extrahieren“): Beleg für Innenraum",
    "Doorways (jamb-to-jamb lines) kept open and made passages":
        "Türöffnungen (Linien von Laibung zu Laibung), offen gehalten und zu Durchgängen gemacht",
    "Area id raster": "Flächenkennungs-Raster",
    "Skeleton (Voronoi graph edges)": "Skelett (Kanten des Voronoi-Graphen)",
    "Rooms": "Räume",
    "Corridors": "Flure",
    "Free area inside the building (m²)": "Freie Fläche im Gebäude (m²)",
    "alpha (px²)": "Alpha (px²)",
    "Segmentation time (s)": "Dauer der Segmentierung (s)",
    "INPUT: '{}' does not exist": "INPUT: '{}' existiert nicht",
    "INPUT: the raster cannot be opened": "INPUT: Das Raster kann nicht geöffnet werden",
    "INPUT: '{}' is not a raster file on disk": "INPUT: '{}' ist keine Rasterdatei auf dem Datenträger",
    "RESOLUTION ignored: the GeoTIFF carries {} m/px": "RESOLUTION ignoriert: Das GeoTIFF hat {} m/px",
    "Grid {} x {} px at {} m/px": "Raster {} x {} px bei {} m/px",
    "{} room-name points used as evidence of inside space":
        "{} Raumnamenpunkte als Beleg für Innenraum verwendet",
    "Footprint evidence: {}": "Beleg durch die Grundfläche: {}",
    "{} stair/lift areas recognised from their symbols": "{} Treppen-/Aufzugsflächen an ihren Symbolen erkannt",
    "Interior free area: {:.1f} m² (of {:.1f} m² free in the raster)":
        "Freie Innenfläche: {:.1f} m² (von {:.1f} m² frei im Raster)",
    "Timing (s): ": "Laufzeiten (s): ",
    "Skeleton: {} nodes, {} edges, {} branches shorter than PRUNE pruned":
        "Skelett: {} Knoten, {} Kanten, {} Äste kürzer als PRUNE entfernt",
    "cannot write area {}": "Fläche {} kann nicht geschrieben werden",
    "cannot write passage {}": "Durchgang {} kann nicht geschrieben werden",
    "cannot write skeleton edge {}": "Skelettkante {} kann nicht geschrieben werden",
    "{} areas ({} rooms, {} corridors), {} passages": "{} Flächen ({} Räume, {} Flure), {} Durchgänge",
    # --- Cad2OsmagProvider
    "CAD to osmAG": "CAD zu osmAG",
    # --- ConvertWizard
    "1. Floor plans": "1. Grundrisse",
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure."):
        ("DXF/DWG-Dateien des Gebäudes wählen, eine je Geschoss (unterstes zuerst). Die Tabelle zeigt die "
         "Layer der gewählten Datei und welche die Regeln als Bauteile behalten."),
    "Add files…": "Dateien hinzufügen…",
    "Remove": "Entfernen",
    "Up": "Nach oben",
    "Down": "Nach unten",
    "Layer": "Layer",
    "Kind": "Art",
    "Kept": "Behalten",
    "Entities": "Objekte",
    "Floor plans": "Grundrisse",
    "CAD drawings (*.dxf *.dwg *.DXF *.DWG)": "CAD-Zeichnungen (*.dxf *.dwg *.DXF *.DWG)",
    "Cannot read the layers of {}.": "Die Layer von {} können nicht gelesen werden.",
    "{}: {} layers, kept: {}": "{}: {} Layer, behalten: {}",
    "2. Segmentation settings (metres)": "2. Segmentierung (Meter)",
    "The defaults suit most buildings. Smaller pixels follow thin walls better but take longer.":
        ("Die Vorgaben passen für die meisten Gebäude. Kleinere Pixel folgen dünnen Wänden besser, dauern "
         "aber länger."),
    "Raster resolution": "Rasterauflösung",
    "Widest door": "Breiteste Tür",
    "Corridor width": "Flurbreite",
    "Merge areas smaller than": "Flächen zusammenführen unter",
    "Level of the first floor": "Geschoss der ersten Datei",
    "Floor height": "Geschosshöhe",
    "Preview the areas of the first floor": "Vorschau der Flächen des ersten Geschosses",
    "Previewing the segmentation": "Vorschau der Segmentierung",
    "Preview failed: {}": "Vorschau gescheitert: {}",
    "canceled": "abgebrochen",
    "Computing…": "Berechnung läuft…",
    "{} areas, {} passages": "{} Flächen, {} Durchgänge",
    "3. Place the plan on the map": "3. Plan auf der Karte platzieren",
    ("Add a basemap, then drag the plan to its place, turn it with the round handle, or click control "
     "points (drawing point, then map point). Every floor uses this placement."):
        ("Hintergrundkarte hinzufügen, den Plan an seinen Ort ziehen, mit dem runden Griff drehen oder "
         "Passpunkte klicken (erst Zeichnung, dann Karte). Gilt für jedes Geschoss."),
    "4. Convert and export": "4. Umwandeln und exportieren",
    "One osmAG file per floor is written to the output folder; the floors are added to the map, styled.":
        ("Eine osmAG-Datei je Geschoss wird in den Ausgabeordner geschrieben; die Geschosse werden "
         "gestaltet zur Karte hinzugefügt."),
    "…": "…",
    "Also write the merged building (building.osm)":
        "Auch das zusammengeführte Gebäude schreiben (building.osm)",
    "Add the styled floors to the map": "Die gestalteten Geschosse zur Karte hinzufügen",
    "Convert": "Umwandeln",
    "Cancel": "Abbrechen",
    "Choose an output folder first.": "Zuerst einen Ausgabeordner wählen.",
    "Converting floor plans to osmAG": "Grundrisse werden in osmAG umgewandelt",
    "Converting {} floor(s)…": "{} Geschoss(e) werden umgewandelt…",
    "Done: {} floor(s) written to {}": "Fertig: {} Geschoss(e) nach {} geschrieben",
    "Stopped: {}": "Angehalten: {}",
    "5. Names and types": "5. Namen und Typen",
    ("Correct the name and the type of any area (room, corridor, stairs, elevator, structure), then save: "
     "the osmAG files are written again."):
        ("Name und Typ jeder Fläche korrigieren (room, corridor, stairs, elevator, structure), dann "
         "speichern: Die osmAG-Dateien werden neu geschrieben."),
    "Area": "Fläche",
    "Name": "Name",
    "Type": "Typ",
    "Save and export again": "Speichern und erneut exportieren",
    "{} areas": "{} Flächen",
    "Exporting osmAG again": "osmAG wird erneut exportiert",
    "Saving {} changed areas…": "{} geänderte Flächen werden gespeichert…",
    "{} areas changed; osmAG files written again.": "{} Flächen geändert; osmAG-Dateien neu geschrieben.",
    "Export failed: {}": "Export gescheitert: {}",
    "Convert a floor plan to osmAG": "Einen Grundriss in osmAG umwandeln",
    # --- Placement
    "the plan has no structure lines to show": "der Plan hat keine Bauteillinien zum Anzeigen",
    "Plan placement: {}": "Platzierung des Plans: {}",
    "the CAD to osmAG Processing provider is not loaded":
        "der Processing-Provider „CAD zu osmAG“ ist nicht geladen",
    "cannot read the structure of {}": "die Bauteile von {} können nicht gelesen werden",
    # --- PlacementDock
    "Load floor plan…": "Grundriss laden…",
    "OSM basemap": "OSM-Hintergrund",
    "Satellite basemap": "Satellitenbild",
    "No plan loaded.": "Kein Plan geladen.",
    "Move / rotate / scale": "Verschieben / drehen / skalieren",
    ("Drag the plan to move it, the round handle to rotate it (Shift: whole degrees), the square handle to "
     "scale it."):
        ("Den Plan ziehen, um ihn zu verschieben, den runden Griff, um ihn zu drehen (Umschalt: ganze "
         "Grad), den quadratischen Griff, um ihn zu skalieren."),
    "Control points": "Passpunkte",
    ("Click a point of the drawing, then the same point on the basemap; repeat (right click cancels a half "
     "pair)."):
        ("Einen Punkt der Zeichnung klicken, dann denselben Punkt auf der Hintergrundkarte; wiederholen "
         "(Rechtsklick verwirft ein halbes Paar)."),
    "Drawing origin longitude": "Länge des Zeichnungsursprungs",
    "Drawing origin latitude": "Breite des Zeichnungsursprungs",
    "Rotation (clockwise from north)": "Drehung (im Uhrzeigersinn von Norden)",
    "Scale (ground m per drawing m)": "Maßstab (Gelände-m je Zeichnungs-m)",
    "Control points: keep the scale (solve position and rotation only)":
        "Passpunkte: Maßstab festhalten (nur Lage und Drehung lösen)",
    "Drawing x (m)": "Zeichnung x (m)",
    "Drawing y (m)": "Zeichnung y (m)",
    "Longitude": "Längengrad",
    "Latitude": "Breitengrad",
    "Residual (m)": "Residuum (m)",
    "RMS: – (add at least 2 control points)": "RMS: – (mindestens 2 Passpunkte setzen)",
    "Remove point": "Punkt entfernen",
    "The placement is saved with the project and used for every floor of the building.":
        "Die Platzierung wird mit dem Projekt gespeichert und für jedes Geschoss des Gebäudes verwendet.",
    "Floor plan": "Grundriss",
    "Cannot load {}: {}": "{} kann nicht geladen werden: {}",
    "{}: {} lines, {:.1f} × {:.1f} m": "{}: {} Linien, {:.1f} × {:.1f} m",
    "Cannot fit: {}": "Anpassung nicht möglich: {}",
    "RMS: {:.3f} m ({} points)": "RMS: {:.3f} m ({} Punkte)",
    "Place the plan on the map": "Plan auf der Karte platzieren",
    # --- Cad2OsmagModel
    ("The whole conversion of one floor as a graphical model of the individual algorithms: extract the "
     "structure of the DXF, rasterize it, segment the free space into an Area Graph (stairs and lifts typed "
     "from the drawing), refine the areas, georeference them (the drawing origin at ANCHOR, ROTATION "
     "clockwise from north, SCALE) and export osmAG. Open it in the graphical modeler to add or change "
     "steps."):
        ("Die ganze Umwandlung eines Geschosses als grafisches Modell der einzelnen Algorithmen: die "
         "Bauteile der DXF extrahieren, rastern, den freien Raum in einen Area Graph segmentieren (Treppen "
         "und Aufzüge aus der Zeichnung typisiert), die Flächen verfeinern, georeferenzieren (der "
         "Zeichnungsursprung bei ANCHOR, ROTATION im Uhrzeigersinn von Norden, SCALE) und als osmAG "
         "exportieren. Im grafischen Modellierer öffnen, um Schritte hinzuzufügen oder zu ändern."),
    ("Where the drawing origin (0, 0) lies on the map: pick it on a basemap, or use the placement of Vector "
     "▸ CAD to osmAG ▸ Place a floor plan on the map."):
        ("Wo der Zeichnungsursprung (0, 0) auf der Karte liegt: auf einer Hintergrundkarte wählen oder die "
         "Platzierung von Vektor ▸ CAD zu osmAG ▸ Einen Grundriss auf der Karte platzieren verwenden."),
    "Corridor width in metres (8 m, the segment default).":
        "Flurbreite in Metern (8 m, die Vorgabe von Segmentieren).",
    "Widest door in metres (2.8 m, the segment default).":
        "Breiteste Tür in Metern (2.8 m, die Vorgabe von Segmentieren).",
    "The floor plan (DXF).": "Der Grundriss (DXF).",
    "Level of the floor (osmAG level tag).": "Geschoss (osmAG-Tag level).",
    "Areas smaller than this (m²) merge into a neighbour (stairs and lifts are kept).":
        ("Flächen kleiner als dieser Wert (m²) werden mit einer Nachbarfläche zusammengeführt (Treppen und "
         "Aufzüge bleiben erhalten)."),
    "The osmAG file written (.osm).": "Die geschriebene osmAG-Datei (.osm).",
    "Raster resolution in metres per pixel (0.044 m by default).":
        "Rasterauflösung in Metern je Pixel (Vorgabe 0.044 m).",
    "Direction of the drawing's +y axis, in degrees clockwise from north.":
        "Richtung der +y-Achse der Zeichnung, in Grad im Uhrzeigersinn von Norden.",
    "Ground metres per drawing metre (1 for a correct drawing).":
        "Meter im Gelände je Zeichnungsmeter (1 für eine maßstabsgetreue Zeichnung).",
    "DXF floor plan": "DXF-Grundriss",
    "osmAG areas (WGS84)": "osmAG-Flächen (WGS84)",
    "osmAG passages (WGS84)": "osmAG-Durchgänge (WGS84)",
    # --- not in the sources of this branch (kept for strings other branches add)
    "Convert DXF floor plan to osmAG": "DXF-Grundriss in osmAG umwandeln",
    "Extract structure from DXF": "Bauteile aus DXF extrahieren",
    "List DXF layers": "DXF-Layer auflisten",
    "DXF drawing": "DXF-Zeichnung",
    "as the inputs": "wie die Eingaben",
    "List the plans on a DXF/DWG sheet": "Die Pläne auf einem DXF/DWG-Blatt auflisten",
    ("Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, and "
     "lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON layer "
     "rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its index "
     "(the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and height "
     "in metres, metres of walls, and main = true for the plan converted by default (index 0 when it is a "
     "plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and legends "
     "left out) to draw the sheet under the rectangles; draw an extent over it to give PLAN_EXTENT. "
     "MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details)."):
        ("Findet die Pläne auf einem ganzen Zeichnungsblatt (DXF oder DWG) wie „Bauteile aus DXF/DWG "
         "extrahieren“ und listet jede Gruppe auf, statt eine zu behalten: INPUT ist die Zeichnung, "
         "LAYER_RULES die optionalen JSON-Layer-Regeln. OUTPUT enthält ein Rechteck je Gruppe, in Metern im "
         "eigenen System der Zeichnung, mit Index (der Wert für PLAN), Art (plan, detail, legend, other), "
         "Titel (z. B. '三层平面图'), Breite und Höhe in Metern, Metern an Wänden und main = true für den "
         "Plan, der als Vorgabe umgewandelt wird (Index 0, wenn es ein Plan ist). STRUCTURE (optional) "
         "enthält die Bauteillinien des ganzen Blatts (ohne Rahmen und Legenden), um das Blatt unter den "
         "Rechtecken zu zeichnen; darüber eine Ausdehnung zeichnen, um PLAN_EXTENT anzugeben. MAIN_PLAN ist "
         "der Index des Hauptplans (-1, wenn das Blatt nur Details enthält)."),
    "Plans on the sheet": "Pläne auf dem Blatt",
    "Structure lines of the whole sheet": "Bauteillinien des ganzen Blatts",
    "Index of the main plan (-1: none)": "Index des Hauptplans (-1: keiner)",
    "plan": "Plan",
    "detail": "Detail",
    "legend": "Legende",
    "other": "Sonstiges",
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure; below, the plans found "
     "on its sheet: the main plan is pre-selected, pick another or draw an extent."):
        ("DXF/DWG-Dateien des Gebäudes wählen, eine je Geschoss (unterstes zuerst). Die Tabelle zeigt die "
         "Layer der gewählten Datei und welche die Regeln als Bauteile behalten; darunter die Pläne ihres "
         "Blatts: Der Hauptplan ist vorgewählt, einen anderen wählen oder eine Ausdehnung zeichnen."),
    "Plans on the sheet (the selected one is converted):":
        "Pläne auf dem Blatt (der gewählte wird umgewandelt):",
    "Plan": "Plan",
    "Size": "Größe",
    "Title": "Titel",
    "Draw an extent on the sheet": "Eine Ausdehnung auf dem Blatt zeichnen",
    ("Drag a rectangle over the sheet to convert only what lies in it (e.g. one half of a floor drawn in "
     "two parts)."):
        ("Ein Rechteck über das Blatt ziehen, um nur umzuwandeln, was darin liegt (z. B. eine Hälfte eines "
         "in zwei Teilen gezeichneten Geschosses)."),
    "Finding the plans on {}": "Pläne auf {} werden gesucht",
    "Finding the plans on the sheet…": "Pläne auf dem Blatt werden gesucht…",
    "plans": "Pläne",
    "sheet": "Blatt",
    "Cannot find the plans: {}": "Die Pläne können nicht gefunden werden: {}",
    "{:.0f} × {:.0f} m": "{:.0f} × {:.0f} m",
    "{} group(s) on the sheet and no floor plan among them: pick one, or draw an extent.":
        "{} Gruppe(n) auf dem Blatt und kein Grundriss darunter: eine wählen oder eine Ausdehnung zeichnen.",
    "Converting the extent {:.1f}, {:.1f} – {:.1f}, {:.1f} m of {} group(s).":
        "Die Ausdehnung {:.1f}, {:.1f} – {:.1f}, {:.1f} m von {} Gruppe(n) wird umgewandelt.",
    "Converting plan [{}] ({}{}) of {} group(s).": "Plan [{}] ({}{}) von {} Gruppe(n) wird umgewandelt.",
    "Snap the rotation to building edges (polygon layers on the map, within 3°)":
        "Drehung an Gebäudekanten einrasten (Polygonlayer auf der Karte, innerhalb von 3°)",
    ("Load building footprints (e.g. OpenStreetMap buildings) as a vector layer: while you turn the plan, "
     "its walls snap to their edges. Shift turns in whole degrees instead."):
        ("Gebäudegrundrisse (z. B. OpenStreetMap-Gebäude) als Vektorlayer laden: Beim Drehen des Plans "
         "rasten seine Wände an ihren Kanten ein. Umschalt dreht stattdessen in ganzen Grad."),
    "Rotation snapped to the building edges at {:.1f}° (modulo 90°).":
        "Drehung an den Gebäudekanten bei {:.1f}° eingerastet (modulo 90°).",
    ("Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, and "
     "lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON layer "
     "rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its index "
     "(the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and height "
     "in metres, metres of walls, and main = true for the plan converted by default (index 0 when it is a "
     "plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and legends "
     "left out) to draw the sheet under the rectangles; draw an extent over it to give PLAN_EXTENT. "
     "MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details). PLAN_COUNT is the "
     "number of groups and PLANS lists them as text."):
        ("Findet die Pläne auf einem ganzen Zeichnungsblatt (DXF oder DWG) wie „Bauteile aus DXF/DWG "
         "extrahieren“ und listet jede Gruppe auf, statt eine zu behalten: INPUT ist die Zeichnung, "
         "LAYER_RULES die optionalen JSON-Layer-Regeln. OUTPUT enthält ein Rechteck je Gruppe, in Metern im "
         "eigenen System der Zeichnung, mit Index (der Wert für PLAN), Art (plan, detail, legend, other), "
         "Titel (z. B. '三层平面图'), Breite und Höhe in Metern, Metern an Wänden und main = true für den "
         "Plan, der als Vorgabe umgewandelt wird (Index 0, wenn es ein Plan ist). STRUCTURE (optional) "
         "enthält die Bauteillinien des ganzen Blatts (ohne Rahmen und Legenden), um das Blatt unter den "
         "Rechtecken zu zeichnen; darüber eine Ausdehnung zeichnen, um PLAN_EXTENT anzugeben. MAIN_PLAN ist "
         "der Index des Hauptplans (-1, wenn das Blatt nur Details enthält). PLAN_COUNT ist die Anzahl der "
         "Gruppen, PLANS listet sie als Text."),
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure; below, the plans found "
     "on its sheet: the main plan is pre-selected, click another (in the list or on the sheet) or draw an "
     "extent."):
        ("DXF/DWG-Dateien des Gebäudes wählen, eine je Geschoss (unterstes zuerst). Die Tabelle zeigt die "
         "Layer der gewählten Datei und welche die Regeln als Bauteile behalten; darunter die Pläne ihres "
         "Blatts: Der Hauptplan ist vorgewählt, einen anderen anklicken (in der Liste oder auf dem Blatt) "
         "oder eine Ausdehnung zeichnen."),
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first), "
     "and check the layers kept as structure and the plan converted on each sheet."):
        'DXF/DWG-Dateien des Gebäudes wählen, eine je Geschoss (unterstes zuerst), und die als Bauteile behaltenen Layer sowie den umgewandelten Plan jedes Blatts prüfen.',
    ("Plans on the sheet: the selected one is converted. The main plan (★) is "
     "pre-selected; click another in the list or on the sheet, or draw an extent."):
        'Pläne auf dem Blatt: der gewählte wird umgewandelt. Der Hauptplan (★) ist vorgewählt; einen anderen in der Liste oder auf dem Blatt anklicken oder einen Ausschnitt zeichnen.',
}

# extractstructure help with the TEXTS layer's hidden field
T["Reads INPUT, a DXF floor plan or a DWG (AutoCAD R13-2018, read directly: no converter needed), explodes blocks (with scale, rotation, mirror and MINSERT arrays; entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.\nLAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). LAYERS: explicit layer names (separated by ';') that override the rules. UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS is set, so that doorways stay open; door swings and door blocks (by name, in many languages) are found on any layer and written as DOORS (jamb to jamb); furniture blocks, free-standing furniture on layer 0 and pattern hatches are left out (the log counts every class).\nWhole sheets: title frames, title blocks and legends are left out and the structure is grouped into plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists every group with its index, extent, title and kind (plan / detail / legend). PLAN picks another (an index, or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.\nOutputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' rebuilds the geometry from them; block, class), TEXTS (points with text, height, rotation, layer, entity, block, tag = ATTRIB tag, id, hidden = on a frozen or off layer; 'Assign room names and types from texts' reads them) and DOORS (doorway lines with source and width). Figures: PLANS (the plans found on the sheet) and PLAN_COUNT (their number), DOOR_COUNT (doorways found), CLASSES (entities counted per class), UNIT and UNIT_SCALE (the unit used and metres per drawing unit), GEOMETRY_COUNT (structure features written) and TEXT_COUNT (texts written)."] = (
    "Liest INPUT, einen DXF-Grundriss oder eine DWG (AutoCAD R13-2018, direkt gelesen: kein Konverter nötig), löst Blöcke auf (mit Skalierung, Drehung, Spiegelung und MINSERT-Anordnungen; Objekte auf Layer 0 in einem Block übernehmen den Layer des INSERT), überspringt gefrorene und ausgeschaltete Layer, behält die von den Layer-Regeln gewählten Bauteil-Layer (Wände, Stützen, Fenster/Verglasung, Treppen, Aufzüge sowie die Referenzlayer 0 und Defpoints) und zerlegt Kurven auf 1 cm genau.\nLAYER_RULES: eine JSON-Datei mit Schlüsselwörtern ohne Beachtung der Groß-/Kleinschreibung (algorithms/default_layer_rules.json kopieren). LAYERS: ausdrückliche Layernamen (durch ';' getrennt), die die Regeln ersetzen. UNITS: $INSUNITS im Dateikopf ist nur ein Hinweis; als Vorgabe wird die Einheit so gewählt, dass das Gebäude 5-500 m groß ist (eine Warnung nennt beide Einheiten). Tür-Layer werden weggelassen, außer INCLUDE_DOORS ist gesetzt, damit Türöffnungen offen bleiben; Türschwenkbögen und Türblöcke (nach Namen, in vielen Sprachen) werden auf jedem Layer gefunden und als DOORS geschrieben (von Laibung zu Laibung); Möbelblöcke, frei stehende Möbel auf Layer 0 und Musterschraffuren werden weggelassen (das Protokoll zählt jede Klasse).\nGanze Blätter: Rahmen, Schriftfelder und Legenden werden weggelassen, und die Bauteile werden in Pläne gruppiert (Gruppen, die mehr als 5 m auseinander liegen); der Hauptplan (größte Wandmasse) wird behalten, das Protokoll listet jede Gruppe mit Index, Ausdehnung, Titel und Art (Plan / Detail / Legende). PLAN wählt einen anderen (ein Index, oder xmin,ymin,xmax,ymax in Metern); PLAN_EXTENT ist dieselbe Ausdehnung, im Kartenfenster gezeichnet.\nAusgaben, in Metern im eigenen System der Zeichnung (ein lokales technisches KBS, nicht georeferenziert): WALLS (Linien mit den Feldern layer, kind, entity, closed, filled, width; „Bauteile rastern“ baut daraus die Geometrie auf; block, class), TEXTS (Punkte mit text, height, rotation, layer, entity, block, tag = ATTRIB-Tag, id, hidden = auf einem gefrorenen oder ausgeschalteten Layer; „Raumnamen und -typen aus Texten zuweisen“ liest sie) und DOORS (Türöffnungslinien mit source und width). Kennzahlen: PLANS (die auf dem Blatt gefundenen Pläne) und PLAN_COUNT (ihre Anzahl), DOOR_COUNT (gefundene Türöffnungen), CLASSES (Objekte je Klasse gezählt), UNIT und UNIT_SCALE (die verwendete Einheit und Meter je Zeichnungseinheit), GEOMETRY_COUNT (geschriebene Bauteilobjekte) und TEXT_COUNT (geschriebene Texte).")

# the model's file input takes DWG too
T['DXF or DWG floor plan'] = 'DXF- oder DWG-Grundriss'
T['The floor plan (DXF, or DWG as delivered: the main plan of a sheet is converted).'] = 'Der Grundriss (DXF, oder DWG wie geliefert: der Hauptplan eines Blatts wird umgewandelt).'

# assignnames: bad input named (issue 9 audit)
T["TEXTS has no 'text' field: use the TEXTS output of 'Extract structure from DXF' (or a point layer with fields text and, optionally, layer, height, rotation, entity, block, tag, id)"] = (
    "TEXTS hat kein Feld 'text': die Ausgabe TEXTS von „Bauteile aus DXF extrahieren“ verwenden (oder einen "
    "Punktlayer mit den Feldern text und, optional, layer, height, rotation, entity, block, tag, id)")
T["AREAS holds no area: nothing to name; every room text is counted as outside every area"] = (
    "AREAS enthält keine Fläche: nichts zu benennen; jeder Raumtext wird als außerhalb jeder Fläche gezählt")
T["TEXTS holds no text: every area gets its generated id (level-area id)"] = (
    "TEXTS enthält keinen Text: jede Fläche erhält ihre erzeugte Kennung (Geschoss-Flächenkennung)")
