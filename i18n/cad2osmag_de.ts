<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
  <context>
    <name>AssignNamesAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Assign room names and types from texts</source>
      <translation>Raumnamen und -typen aus Texten zuweisen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Names, numbers and types the AREAS from the drawing's TEXTS (the text output of 'Extract structure from DXF', with block attributes).
Which texts are room names: configurable rules (NAME_RULES, a copy of algorithms/default_name_rules.json) classify every text as a room name, a room number (kept as ref) or ignored, with the reason (dimension, area, elevation, door/window code, axis, stair arrow, note, title, title block, furniture...), using the text itself, the layer it sits on (room-name layers such as A-ANNO-ROOM, *-SYMB-NAME, 房间; bound-xref prefixes are stripped) and its block and attribute tag. Lines of a multi-line TEXT label are joined first.
Which area: every text is scored against every area as in the CAD-to-osmAG paper (inside: 100 - 50 rho up to rho_max 0.7, then 50 - 25 (rho - 0.7); outside but within 2.2 m of the border: 40 + 30 f_size + 20 f_dist) and goes to its best area; a text inside an area belongs to it. Name and number join; an area holding two different room names is split at the narrowing between them (SPLIT, grown from the cores of its clearance map; a corridor between them becomes its own area), else it keeps the best-placed name and lists the others in label_conflict. Duplicate names get a suffix (the room number, else (1), (2)...); areas without text get the stable id level-area id (e.g. 2-17).
Types: keywords (English, Italian, Spanish, German, French, Chinese...) and codes (*-ST-* stairs, *-P1/*-OP-*/*-FG-* lifts) set type stairs/elevator/corridor/room and the Simple Indoor Tagging fields indoor and room; long, narrow unnamed areas with three or more passages become corridors.
Edit name, ref or type in the output layer to fix them: 'Export osmAG' keeps the edits and the passages follow renamed areas. TEXT_REPORT (optional) lists every label with its role, reason, area and score.
PASSAGES (optional): the passages of the areas; split areas get theirs, and corridors are recognised by their number of passages. LEVEL: the level used in generated ids (empty: the areas' level field, else 1).
Outputs: OUTPUT_AREAS, the named areas (fields name, ref, type, indoor, room, label_conflict); OUTPUT_PASSAGES, the passages including those of split areas; counts NAMED (areas named from the drawing), NUMBERED (with a room number), AUTO_IDS (with a generated id), CONFLICTS (holding several names), SPLITS (areas split), IGNORED (texts ignored) and OUTSIDE (room texts outside every area).</source>
      <translation>Benennt, nummeriert und typisiert die AREAS (Flächen) anhand der TEXTS der Zeichnung (die Textausgabe von „Bauteile aus DXF extrahieren“, mit Blockattributen).
Welche Texte Raumnamen sind: konfigurierbare Regeln (NAME_RULES, eine Kopie von algorithms/default_name_rules.json) ordnen jeden Text als Raumname, Raumnummer (als ref übernommen) oder ignoriert ein, mit Begründung (Bemaßung, Fläche, Höhenkote, Tür-/Fensterkennung, Achse, Treppenpfeil, Notiz, Titel, Schriftfeld, Möbel …), anhand des Textes selbst, des Layers, auf dem er liegt (Raumnamen-Layer wie A-ANNO-ROOM, *-SYMB-NAME, 房间; Präfixe gebundener externer Referenzen werden entfernt), sowie seines Blocks und Attribut-Tags. Die Zeilen eines mehrzeiligen TEXT-Labels werden zuerst zusammengefügt.
Welche Fläche: Jeder Text wird wie im CAD-to-osmAG-Artikel gegen jede Fläche bewertet (innen: 100 - 50 rho bis rho_max 0.7, danach 50 - 25 (rho - 0.7); außen, aber höchstens 2.2 m vom Rand: 40 + 30 f_size + 20 f_dist) und geht an seine beste Fläche; ein Text innerhalb einer Fläche gehört zu ihr. Name und Nummer werden verbunden; eine Fläche mit zwei verschiedenen Raumnamen wird an der Engstelle zwischen ihnen geteilt (SPLIT, von den Kernen ihrer Freiraumkarte aus gewachsen; ein Flur dazwischen wird eine eigene Fläche), andernfalls behält sie den am besten platzierten Namen und führt die übrigen in label_conflict auf. Doppelte Namen erhalten einen Zusatz (die Raumnummer, sonst (1), (2) …); Flächen ohne Text erhalten die stabile Kennung Geschoss-Flächenkennung (z. B. 2-17).
Typen: Schlüsselwörter (Englisch, Italienisch, Spanisch, Deutsch, Französisch, Chinesisch …) und Kennungen (*-ST-* Treppen, *-P1/*-OP-*/*-FG-* Aufzüge) setzen den Typ stairs/elevator/corridor/room und die Simple-Indoor-Tagging-Felder indoor und room; lange, schmale unbenannte Flächen mit drei oder mehr Durchgängen werden Flure.
Zum Korrigieren name, ref oder type in der Ausgabelayer bearbeiten: „osmAG exportieren“ übernimmt die Änderungen, und die Durchgänge folgen umbenannten Flächen. TEXT_REPORT (optional) listet jedes Label mit Rolle, Begründung, Fläche und Bewertung.
PASSAGES (optional): die Durchgänge der Flächen; geteilte Flächen erhalten ihre eigenen, und Flure werden an der Zahl ihrer Durchgänge erkannt. LEVEL: das Geschoss in erzeugten Kennungen (leer: das Feld level der Flächen, sonst 1).
Ausgaben: OUTPUT_AREAS, die benannten Flächen (Felder name, ref, type, indoor, room, label_conflict); OUTPUT_PASSAGES, die Durchgänge einschließlich derer geteilter Flächen; die Anzahlen NAMED (aus der Zeichnung benannte Flächen), NUMBERED (mit Raumnummer), AUTO_IDS (mit erzeugter Kennung), CONFLICTS (mit mehreren Namen), SPLITS (geteilte Flächen), IGNORED (ignorierte Texte) und OUTSIDE (Raumtexte außerhalb jeder Fläche).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas</source>
      <translation>Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Texts (from 'Extract structure from DXF')</source>
      <translation>Texte (aus „Bauteile aus DXF extrahieren“)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Passages (optional: split areas get their passages, corridors their degree)</source>
      <translation>Durchgänge (optional: geteilte Flächen erhalten ihre Durchgänge, Flure ihren Grad)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Level (for generated ids; empty: the areas' level field, else 1)</source>
      <translation>Geschoss (für erzeugte Kennungen; leer: Feld level der Flächen, sonst 1)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Name rules (JSON, empty = built-in defaults)</source>
      <translation>Namensregeln (JSON, leer = eingebaute Regeln)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Split areas holding two room names at the narrowing between them</source>
      <translation>Flächen mit zwei Raumnamen an der Engstelle dazwischen teilen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Named areas</source>
      <translation>Benannte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Passages (with those of split areas)</source>
      <translation>Durchgänge (mit denen geteilter Flächen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Text report (role, reason, area of every label)</source>
      <translation>Textbericht (Rolle, Begründung, Fläche jedes Labels)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas named from the drawing</source>
      <translation>Aus der Zeichnung benannte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas with a room number</source>
      <translation>Flächen mit Raumnummer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas with a generated id</source>
      <translation>Flächen mit erzeugter Kennung</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas holding several names</source>
      <translation>Flächen mit mehreren Namen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas split</source>
      <translation>Geteilte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Texts ignored</source>
      <translation>Ignorierte Texte</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Room texts outside every area</source>
      <translation>Raumtexte außerhalb jeder Fläche</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation>AREAS: Der Eingabelayer kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS: the input layer cannot be opened</source>
      <translation>TEXTS: Der Eingabelayer kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS</source>
      <translation>TEXTS</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>PASSAGES</source>
      <translation>PASSAGES</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>{} is in {} but AREAS is in {}: reproject it to the CRS of AREAS first</source>
      <translation>{} liegt in {}, AREAS aber in {}: zuerst in das KBS von AREAS umprojizieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>AREAS is in a geographic CRS (degrees); the scores use metres: run this on the CAD-frame layers (before georeferencing) or reproject to a projected CRS</source>
      <translation>AREAS liegt in einem geographischen KBS (Grad); die Bewertung rechnet in Metern: auf den Layern im CAD-System ausführen (vor dem Georeferenzieren) oder in ein projiziertes KBS umprojizieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>AREAS holds no area: nothing to name; every room text is counted as outside every area</source>
      <translation>AREAS enthält keine Fläche: nichts zu benennen; jeder Raumtext wird als außerhalb jeder Fläche gezählt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS holds no text: every area gets its generated id (level-area id)</source>
      <translation>TEXTS enthält keinen Text: jede Fläche erhält ihre erzeugte Kennung (Geschoss-Flächenkennung)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>cannot write area {} to the output layer</source>
      <translation>Fläche {} kann nicht in den Ausgabelayer geschrieben werden</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS has no 'text' field: use the TEXTS output of 'Extract structure from DXF' (or a point layer with fields text and, optionally, layer, height, rotation, entity, block, tag, id)</source>
      <translation>TEXTS hat kein Feld 'text': die Ausgabe TEXTS von „Bauteile aus DXF extrahieren“ verwenden (oder einen Punktlayer mit den Feldern text und, optional, layer, height, rotation, entity, block, tag, id)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Plan on the sheet (empty = main plan; an index of the log's plan list, or xmin,ymin,xmax,ymax in metres)</source>
      <translation>Plan auf dem Blatt (leer = Hauptplan; ein Index der Planliste im Protokoll, oder xmin,ymin,xmax,ymax in Metern)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Plan extent (drawn on the canvas over the extracted structure; wins over PLAN)</source>
      <translation>Planausdehnung (im Kartenfenster über den extrahierten Bauteilen gezeichnet; hat Vorrang vor PLAN)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>the point {}, {} [{}] cannot be converted to longitude/latitude: {}</source>
      <translation>der Punkt {}, {} [{}] kann nicht in Länge/Breite umgerechnet werden: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>style not stored in {}: {}</source>
      <translation>Stil nicht in {} gespeichert: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>cannot convert to {}: {}</source>
      <translation>Umrechnung nach {} nicht möglich: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>unclosed area ways (skipped): {}</source>
      <translation>nicht geschlossene Flächenwege (übersprungen): {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>dangling references (skipped): nodes {} refs {}</source>
      <translation>verwaiste Verweise (übersprungen): Knoten {} Verweise {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>{}: features with ids {} have empty or missing geometries; remove them or fix the layer</source>
      <translation>{}: Die Objekte mit den Kennungen {} haben leere oder fehlende Geometrien; sie entfernen oder den Layer reparieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>PASSAGES: passage {} has no valid {} (value {!r}); it must name the id of an area</source>
      <translation>PASSAGES: Durchgang {} hat kein gültiges {} (Wert {!r}); es muss die Kennung einer Fläche nennen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>PASSAGES: passage {} has no line geometry</source>
      <translation>PASSAGES: Durchgang {} hat keine Liniengeometrie</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>cannot write area {} to the output layer</source>
      <translation>Fläche {} kann nicht in den Ausgabelayer geschrieben werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>cannot write passage {} to the output layer</source>
      <translation>Durchgang {} kann nicht in den Ausgabelayer geschrieben werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>Canceled by the user.</source>
      <translation>Vom Benutzer abgebrochen.</translation>
    </message>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>DXF or DWG drawing</source>
      <translation>DXF- oder DWG-Zeichnung</translation>
    </message>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>Layer rules (JSON, empty = built-in defaults)</source>
      <translation>Layer-Regeln (JSON, leer = eingebaute Regeln)</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagModel</name>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>The whole conversion of one floor as a graphical model of the individual algorithms: extract the structure of the DXF, rasterize it, segment the free space into an Area Graph (stairs and lifts typed from the drawing), refine the areas, georeference them (the drawing origin at ANCHOR, ROTATION clockwise from north, SCALE) and export osmAG. Open it in the graphical modeler to add or change steps.</source>
      <translation>Die ganze Umwandlung eines Geschosses als grafisches Modell der einzelnen Algorithmen: die Bauteile der DXF extrahieren, rastern, den freien Raum in einen Area Graph segmentieren (Treppen und Aufzüge aus der Zeichnung typisiert), die Flächen verfeinern, georeferenzieren (der Zeichnungsursprung bei ANCHOR, ROTATION im Uhrzeigersinn von Norden, SCALE) und als osmAG exportieren. Im grafischen Modellierer öffnen, um Schritte hinzuzufügen oder zu ändern.</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Where the drawing origin (0, 0) lies on the map: pick it on a basemap, or use the placement of Vector ▸ CAD to osmAG ▸ Place a floor plan on the map.</source>
      <translation>Wo der Zeichnungsursprung (0, 0) auf der Karte liegt: auf einer Hintergrundkarte wählen oder die Platzierung von Vektor ▸ CAD zu osmAG ▸ Einen Grundriss auf der Karte platzieren verwenden.</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Corridor width in metres (8 m, the segment default).</source>
      <translation>Flurbreite in Metern (8 m, die Vorgabe von Segmentieren).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Widest door in metres (2.8 m, the segment default).</source>
      <translation>Breiteste Tür in Metern (2.8 m, die Vorgabe von Segmentieren).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>The floor plan (DXF, or DWG as delivered: the main plan of a sheet is converted).</source>
      <translation>Der Grundriss (DXF, oder DWG wie geliefert: der Hauptplan eines Blatts wird umgewandelt).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Level of the floor (osmAG level tag).</source>
      <translation>Geschoss (osmAG-Tag level).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Areas smaller than this (m²) merge into a neighbour (stairs and lifts are kept).</source>
      <translation>Flächen kleiner als dieser Wert (m²) werden mit einer Nachbarfläche zusammengeführt (Treppen und Aufzüge bleiben erhalten).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>The osmAG file written (.osm).</source>
      <translation>Die geschriebene osmAG-Datei (.osm).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Raster resolution in metres per pixel (0.044 m by default).</source>
      <translation>Rasterauflösung in Metern je Pixel (Vorgabe 0.044 m).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Direction of the drawing's +y axis, in degrees clockwise from north.</source>
      <translation>Richtung der +y-Achse der Zeichnung, in Grad im Uhrzeigersinn von Norden.</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Ground metres per drawing metre (1 for a correct drawing).</source>
      <translation>Meter im Gelände je Zeichnungsmeter (1 für eine maßstabsgetreue Zeichnung).</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Position of the drawing origin</source>
      <translation>Lage des Zeichnungsursprungs</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Narrowest corridor (m)</source>
      <translation>Schmalster Flur (m)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Widest door (m)</source>
      <translation>Breiteste Tür (m)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>DXF or DWG floor plan</source>
      <translation>DXF- oder DWG-Grundriss</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Level</source>
      <translation>Geschoss</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Merge areas smaller than (m²)</source>
      <translation>Flächen zusammenführen, die kleiner sind als (m²)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Raster resolution (m/px)</source>
      <translation>Rasterauflösung (m/px)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Rotation (degrees clockwise from north)</source>
      <translation>Drehung (Grad im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>Scale (ground metres per drawing metre)</source>
      <translation>Maßstab (Meter im Gelände je Zeichnungsmeter)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>osmAG file</source>
      <translation>osmAG-Datei</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>osmAG areas (WGS84)</source>
      <translation>osmAG-Flächen (WGS84)</translation>
    </message>
    <message>
      <location filename="../models/cad_to_osmag.model3" />
      <source>osmAG passages (WGS84)</source>
      <translation>osmAG-Durchgänge (WGS84)</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagPlugin</name>
    <message>
      <location filename="../plugin.py" />
      <source>Convert a DXF floor plan to osmAG…</source>
      <translation>DXF-Grundriss in osmAG umwandeln…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Show the CAD to osmAG algorithms</source>
      <translation>Die CAD-zu-osmAG-Algorithmen anzeigen</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Convert a floor plan…</source>
      <translation>Einen Grundriss umwandeln…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Place a floor plan on the map…</source>
      <translation>Einen Grundriss auf der Karte platzieren…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Add OpenStreetMap basemap</source>
      <translation>OpenStreetMap-Hintergrundkarte hinzufügen</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Add satellite imagery basemap</source>
      <translation>Satellitenbild-Hintergrundkarte hinzufügen</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Added basemap “{}”.</source>
      <translation>Hintergrundkarte „{}“ hinzugefügt.</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagProvider</name>
    <message>
      <location filename="../processing_provider/provider.py" />
      <source>CAD to osmAG</source>
      <translation>CAD zu osmAG</translation>
    </message>
  </context>
  <context>
    <name>ConvertWizard</name>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>plan</source>
      <translation>Plan</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>detail</source>
      <translation>Detail</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>legend</source>
      <translation>Legende</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>other</source>
      <translation>Sonstiges</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>1. Floor plans</source>
      <translation>1. Grundrisse</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Pick the DXF/DWG files of the building, one per floor (bottom floor first), and check the layers kept as structure and the plan converted on each sheet.</source>
      <translation>DXF/DWG-Dateien des Gebäudes wählen, eine je Geschoss (unterstes zuerst), und die als Bauteile behaltenen Layer sowie den umgewandelten Plan jedes Blatts prüfen.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add files…</source>
      <translation>Dateien hinzufügen…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Remove</source>
      <translation>Entfernen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Up</source>
      <translation>Nach oben</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Down</source>
      <translation>Nach unten</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Layer</source>
      <translation>Layer</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Kind</source>
      <translation>Art</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Kept</source>
      <translation>Behalten</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Entities</source>
      <translation>Objekte</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Plans on the sheet: the selected one is converted. The main plan (★) is pre-selected; click another in the list or on the sheet, or draw an extent.</source>
      <translation>Pläne auf dem Blatt: der gewählte wird umgewandelt. Der Hauptplan (★) ist vorgewählt; einen anderen in der Liste oder auf dem Blatt anklicken oder einen Ausschnitt zeichnen.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Plan</source>
      <translation>Plan</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Size</source>
      <translation>Größe</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Title</source>
      <translation>Titel</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Draw an extent on the sheet</source>
      <translation>Eine Ausdehnung auf dem Blatt zeichnen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Drag a rectangle over the sheet to convert only what lies in it (e.g. one half of a floor drawn in two parts).</source>
      <translation>Ein Rechteck über das Blatt ziehen, um nur umzuwandeln, was darin liegt (z. B. eine Hälfte eines in zwei Teilen gezeichneten Geschosses).</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Floor plans</source>
      <translation>Grundrisse</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>CAD drawings (*.dxf *.dwg *.DXF *.DWG)</source>
      <translation>CAD-Zeichnungen (*.dxf *.dwg *.DXF *.DWG)</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Cannot read the layers of {}.</source>
      <translation>Die Layer von {} können nicht gelesen werden.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>yes</source>
      <translation>ja</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>no</source>
      <translation>nein</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{}: {} layers, kept: {}</source>
      <translation>{}: {} Layer, behalten: {}</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Finding the plans on {}</source>
      <translation>Pläne auf {} werden gesucht</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Finding the plans on the sheet…</source>
      <translation>Pläne auf dem Blatt werden gesucht…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>canceled</source>
      <translation>abgebrochen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>plans</source>
      <translation>Pläne</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>sheet</source>
      <translation>Blatt</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Cannot find the plans: {}</source>
      <translation>Die Pläne können nicht gefunden werden: {}</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{:.0f} × {:.0f} m</source>
      <translation>{:.0f} × {:.0f} m</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} group(s) on the sheet and no floor plan among them: pick one, or draw an extent.</source>
      <translation>{} Gruppe(n) auf dem Blatt und kein Grundriss darunter: eine wählen oder eine Ausdehnung zeichnen.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting the extent {:.1f}, {:.1f} – {:.1f}, {:.1f} m of {} group(s).</source>
      <translation>Die Ausdehnung {:.1f}, {:.1f} – {:.1f}, {:.1f} m von {} Gruppe(n) wird umgewandelt.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting plan [{}] ({}{}) of {} group(s).</source>
      <translation>Plan [{}] ({}{}) von {} Gruppe(n) wird umgewandelt.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>2. Segmentation settings (metres)</source>
      <translation>2. Segmentierung (Meter)</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>The defaults suit most buildings. Smaller pixels follow thin walls better but take longer.</source>
      <translation>Die Vorgaben passen für die meisten Gebäude. Kleinere Pixel folgen dünnen Wänden besser, dauern aber länger.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Raster resolution</source>
      <translation>Rasterauflösung</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Widest door</source>
      <translation>Breiteste Tür</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Corridor width</source>
      <translation>Flurbreite</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Merge areas smaller than</source>
      <translation>Flächen zusammenführen unter</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Level of the first floor</source>
      <translation>Geschoss der ersten Datei</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Floor height</source>
      <translation>Geschosshöhe</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Preview the areas of the first floor</source>
      <translation>Vorschau der Flächen des ersten Geschosses</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Previewing the segmentation</source>
      <translation>Vorschau der Segmentierung</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Preview failed: {}</source>
      <translation>Vorschau gescheitert: {}</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Computing…</source>
      <translation>Berechnung läuft…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas, {} passages</source>
      <translation>{} Flächen, {} Durchgänge</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>3. Place the plan on the map</source>
      <translation>3. Plan auf der Karte platzieren</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add a basemap, then drag the plan to its place, turn it with the round handle, or click control points (drawing point, then map point). Every floor uses this placement.</source>
      <translation>Hintergrundkarte hinzufügen, den Plan an seinen Ort ziehen, mit dem runden Griff drehen oder Passpunkte klicken (erst Zeichnung, dann Karte). Gilt für jedes Geschoss.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>4. Convert and export</source>
      <translation>4. Umwandeln und exportieren</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>One osmAG file per floor is written to the output folder; the floors are added to the map, styled.</source>
      <translation>Eine osmAG-Datei je Geschoss wird in den Ausgabeordner geschrieben; die Geschosse werden gestaltet zur Karte hinzugefügt.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>…</source>
      <translation>…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Output folder</source>
      <translation>Ausgabeordner</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Also write the merged building (building.osm)</source>
      <translation>Auch das zusammengeführte Gebäude schreiben (building.osm)</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add the styled floors to the map</source>
      <translation>Die gestalteten Geschosse zur Karte hinzufügen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Convert</source>
      <translation>Umwandeln</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Cancel</source>
      <translation>Abbrechen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Choose an output folder first.</source>
      <translation>Zuerst einen Ausgabeordner wählen.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting floor plans to osmAG</source>
      <translation>Grundrisse werden in osmAG umgewandelt</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting {} floor(s)…</source>
      <translation>{} Geschoss(e) werden umgewandelt…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Done: {} floor(s) written to {}</source>
      <translation>Fertig: {} Geschoss(e) nach {} geschrieben</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Stopped: {}</source>
      <translation>Angehalten: {}</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>5. Names and types</source>
      <translation>5. Namen und Typen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Correct the name and the type of any area (room, corridor, stairs, elevator, structure), then save: the osmAG files are written again.</source>
      <translation>Name und Typ jeder Fläche korrigieren (room, corridor, stairs, elevator, structure), dann speichern: Die osmAG-Dateien werden neu geschrieben.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Level</source>
      <translation>Geschoss</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Area</source>
      <translation>Fläche</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Name</source>
      <translation>Name</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Type</source>
      <translation>Typ</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Save and export again</source>
      <translation>Speichern und erneut exportieren</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas</source>
      <translation>{} Flächen</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Exporting osmAG again</source>
      <translation>osmAG wird erneut exportiert</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Saving {} changed areas…</source>
      <translation>{} geänderte Flächen werden gespeichert…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas changed; osmAG files written again.</source>
      <translation>{} Flächen geändert; osmAG-Dateien neu geschrieben.</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Export failed: {}</source>
      <translation>Export gescheitert: {}</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Convert a floor plan to osmAG</source>
      <translation>Einen Grundriss in osmAG umwandeln</translation>
    </message>
  </context>
  <context>
    <name>DxfToOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Convert DXF/DWG floor plan to osmAG</source>
      <translation>DXF/DWG-Grundriss in osmAG umwandeln</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Runs the whole pipeline on one floor (a DXF, or a DWG of AutoCAD R13-2018 read directly): structural layers of the drawing are kept (walls, columns, glazing, stairs), rasterized, segmented into an Area Graph of rooms, corridors and the passages between them, refined (simplified polygons with shared borders) and written as an osmAG file anchored on the Earth. Each step is also available as its own algorithm for finer control.
INPUT: the floor plan (.dxf or .dwg). LAYER_RULES: a JSON file of layer keywords (empty: the built-in rules; see 'List DXF/DWG layers'). UNITS: the unit the drawing is drawn in (auto: read from the header and checked for a plausible building size).
RESOLUTION: raster pixel size in metres (0.044 m by default; smaller follows thin walls better but is slower). TOPOLOGY_CELL: the cell size (m) of the segmentation's skeleton and merges (0.088 m, two raster pixels; the outlines keep the raster's pixels; 0 = the raster's pixels, slower). DOOR_WIDTH: the widest door in metres (2.8 m): narrower openings separate rooms. CORRIDOR_WIDTH: corridor width in metres (8 m). MIN_AREA: areas smaller than this (m²) merge into a neighbour (stairs and lifts are kept). INCLUDE_DOORS: draw door layers as walls (doorways closed; off by default, so that doorways stay open).
PLAN / PLAN_EXTENT: which plan of a sheet with several (empty: the main plan; an index of the plan list in the log, or xmin,ymin,xmax,ymax in metres, or an extent drawn on the canvas).
NAMES (on by default): the drawing's texts name, number and type the areas (see 'Assign room names and types from texts'); NAME_RULES: a JSON file that adapts those rules.
LEVEL: the floor's level (osmAG level tag, e.g. 1, -1). HEIGHT: floor height in metres (3.2 m). ANCHOR: where the drawing origin (0, 0) lies on the map (pick it on a basemap; empty: longitude 0, latitude 0). ROTATION: the direction of the drawing's +y axis in degrees clockwise from north. VARIANT: semantic (passages name their areas) or fix-id (passages give way ids).
Outputs: OUTPUT, the osmAG file (.osm); OUTPUT_AREAS and OUTPUT_PASSAGES, the same areas and passages as layers in WGS84 to show on the map; PREVIEW, an optional PNG picture of the areas; AREA_COUNT and PASSAGE_COUNT, the numbers written.</source>
      <translation>Führt die ganze Verarbeitungskette für ein Geschoss aus (eine DXF oder eine DWG von AutoCAD R13-2018, direkt gelesen): Die Bauteil-Layer der Zeichnung werden behalten (Wände, Stützen, Verglasung, Treppen), gerastert, in einen Area Graph aus Räumen, Fluren und den Durchgängen dazwischen segmentiert, verfeinert (vereinfachte Polygone mit gemeinsamen Kanten) und als osmAG-Datei geschrieben, auf der Erde verankert. Jeder Schritt ist auch als eigener Algorithmus verfügbar, für genauere Kontrolle.
INPUT: der Grundriss (.dxf oder .dwg). LAYER_RULES: eine JSON-Datei mit Layer-Schlüsselwörtern (leer: die eingebauten Regeln; siehe „DXF/DWG-Layer auflisten“). UNITS: die Einheit, in der die Zeichnung gezeichnet ist (auto: aus dem Dateikopf gelesen und auf eine plausible Gebäudegröße geprüft).
RESOLUTION: Pixelgröße des Rasters in Metern (0.044 m als Vorgabe; kleiner folgt dünnen Wänden besser, ist aber langsamer). TOPOLOGY_CELL: die Zellgröße (m) von Skelett und Zusammenführungen der Segmentierung (0.088 m, zwei Rasterpixel; die Umrisse behalten die Pixel des Rasters; 0 = die Pixel des Rasters, langsamer). DOOR_WIDTH: die breiteste Tür in Metern (2.8 m): schmalere Öffnungen trennen Räume. CORRIDOR_WIDTH: Flurbreite in Metern (8 m). MIN_AREA: Flächen kleiner als dieser Wert (m²) werden mit einer Nachbarfläche zusammengeführt (Treppen und Aufzüge bleiben erhalten). INCLUDE_DOORS: Tür-Layer als Wände zeichnen (Türöffnungen geschlossen; als Vorgabe aus, damit Türöffnungen offen bleiben).
PLAN / PLAN_EXTENT: welcher Plan eines Blatts mit mehreren (leer: der Hauptplan; ein Index der Planliste im Protokoll, oder xmin,ymin,xmax,ymax in Metern, oder eine im Kartenfenster gezeichnete Ausdehnung).
NAMES (als Vorgabe an): Die Texte der Zeichnung benennen, nummerieren und typisieren die Flächen (siehe „Raumnamen und -typen aus Texten zuweisen“); NAME_RULES: eine JSON-Datei, die diese Regeln anpasst.
LEVEL: das Geschoss (osmAG-Tag level, z. B. 1, -1). HEIGHT: Geschosshöhe in Metern (3.2 m). ANCHOR: wo der Zeichnungsursprung (0, 0) auf der Karte liegt (auf einer Hintergrundkarte wählen; leer: Längengrad 0, Breitengrad 0). ROTATION: die Richtung der +y-Achse der Zeichnung in Grad im Uhrzeigersinn von Norden. VARIANT: semantic (Durchgänge nennen ihre Flächen beim Namen) oder fix-id (Durchgänge geben Weg-Kennungen an).
Ausgaben: OUTPUT, die osmAG-Datei (.osm); OUTPUT_AREAS und OUTPUT_PASSAGES, dieselben Flächen und Durchgänge als Layer in WGS84 zur Anzeige auf der Karte; PREVIEW, ein optionales PNG-Bild der Flächen; AREA_COUNT und PASSAGE_COUNT, die geschriebenen Anzahlen.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>DXF or DWG floor plan</source>
      <translation>DXF- oder DWG-Grundriss</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Layer rules (JSON, optional)</source>
      <translation>Layer-Regeln (JSON, optional)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Drawing units</source>
      <translation>Zeichnungseinheiten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Raster resolution (m/px)</source>
      <translation>Rasterauflösung (m/px)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Cell size of the skeleton and merges (m; 0 = the raster's cells)</source>
      <translation>Zellgröße von Skelett und Zusammenführungen (m; 0 = die Zellen des Rasters)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Widest door (m)</source>
      <translation>Breiteste Tür (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Corridor width (m)</source>
      <translation>Flurbreite (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>Flächen zusammenführen, die kleiner sind als (m²)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Close doorways (rasterize door layers)</source>
      <translation>Türöffnungen schließen (Tür-Layer rastern)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Room names, numbers and types from the drawing's texts</source>
      <translation>Raumnamen, -nummern und -typen aus den Texten der Zeichnung</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Name rules (JSON, optional)</source>
      <translation>Namensregeln (JSON, optional)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Level</source>
      <translation>Geschoss</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Floor height (m)</source>
      <translation>Geschosshöhe (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Position of the drawing origin</source>
      <translation>Lage des Zeichnungsursprungs</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Rotation (degrees clockwise from north)</source>
      <translation>Drehung (Grad im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>osmAG variant</source>
      <translation>osmAG-Variante</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG-Datei</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation>OpenStreetMap-XML (*.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Areas (to show on the map)</source>
      <translation>Flächen (zur Anzeige auf der Karte)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Passages (to show on the map)</source>
      <translation>Durchgänge (zur Anzeige auf der Karte)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Preview image</source>
      <translation>Vorschaubild</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>PNG image (*.png)</source>
      <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Areas</source>
      <translation>Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Passages</source>
      <translation>Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>OUTPUT: give the .osm file to write</source>
      <translation>OUTPUT: die zu schreibende .osm-Datei angeben</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Stage times: {}</source>
      <translation>Laufzeiten der Schritte: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>auto</source>
      <translation>automatisch</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>mm</source>
      <translation>mm</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>cm</source>
      <translation>cm</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>m</source>
      <translation>m</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>inch</source>
      <translation>Zoll</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>feet</source>
      <translation>Fuß</translation>
    </message>
  </context>
  <context>
    <name>DxfToOsmagBatchAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Convert a folder of floor plans to osmAG (parallel)</source>
      <translation>Einen Ordner mit Grundrissen in osmAG umwandeln (parallel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Converts every floor plan of FOLDER (files matching PATTERN, e.g. '*.dxf') with the whole pipeline of 'Convert DXF floor plan to osmAG', several files at once: WORKERS processes (0 = one per processor core). Each file writes OUTPUT_FOLDER/NAME.osm (NAME: the drawing's file name). A file that fails (not a drawing, no walls, …) is reported with its reason and never stops the others.
FIRST_LEVEL: the level of the first file in natural name order (floor-2 before floor-10); each next file is one level up. HEIGHT: floor height in metres.
Placement, the same for every floor: ANCHOR is where the drawing origin (0, 0) lies (pick it on the map), ROTATION the direction of the drawing's +y axis in degrees clockwise from north, SCALE ground metres per drawing metre. Without ANCHOR the placement saved in the project by 'Place a floor plan on the map' is used, if any.
RESOLUTION (m/px), DOOR_WIDTH and CORRIDOR_WIDTH (m), MIN_AREA (m²): as in the single-file algorithm. MERGE also writes OUTPUT_FOLDER/building.osm with every converted floor.
REPORT: a CSV with one row per file (file, level, status, areas, passages, seconds, message).
Outputs: SUCCEEDED and FAILED, the numbers of floors converted and failed (one bad file never stops the others), and OUTPUT_FOLDER.</source>
      <translation>Wandelt jeden Grundriss in FOLDER (Dateien, die auf PATTERN passen, z. B. '*.dxf') mit der ganzen Verarbeitungskette von „DXF-Grundriss in osmAG umwandeln“ um, mehrere Dateien gleichzeitig: WORKERS Prozesse (0 = einer je Prozessorkern). Jede Datei schreibt OUTPUT_FOLDER/NAME.osm (NAME: der Dateiname der Zeichnung). Eine Datei, die scheitert (keine Zeichnung, keine Wände, …), wird mit ihrem Grund gemeldet und hält die anderen nie auf.
FIRST_LEVEL: das Geschoss der ersten Datei in natürlicher Namensreihenfolge (floor-2 vor floor-10); jede weitere Datei liegt ein Geschoss höher. HEIGHT: Geschosshöhe in Metern.
Platzierung, für jedes Geschoss gleich: ANCHOR ist der Ort des Zeichnungsursprungs (0, 0) (auf der Karte wählen), ROTATION die Richtung der +y-Achse der Zeichnung in Grad im Uhrzeigersinn von Norden, SCALE Meter im Gelände je Zeichnungsmeter. Ohne ANCHOR wird die mit „Einen Grundriss auf der Karte platzieren“ im Projekt gespeicherte Platzierung verwendet, falls vorhanden.
RESOLUTION (m/px), DOOR_WIDTH und CORRIDOR_WIDTH (m), MIN_AREA (m²): wie im Algorithmus für eine Datei. MERGE schreibt zusätzlich OUTPUT_FOLDER/building.osm mit jedem umgewandelten Geschoss.
REPORT: eine CSV-Datei mit einer Zeile je Datei (Datei, Geschoss, Status, Flächen, Durchgänge, Sekunden, Meldung).
Ausgaben: SUCCEEDED und FAILED, die Anzahl umgewandelter und gescheiterter Geschosse (eine fehlerhafte Datei hält die anderen nie auf), und OUTPUT_FOLDER.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Folder of floor plans</source>
      <translation>Ordner mit Grundrissen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>File name patterns (';' separated)</source>
      <translation>Dateinamensmuster (durch ';' getrennt)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Level of the first file</source>
      <translation>Geschoss der ersten Datei</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floor height (m)</source>
      <translation>Geschosshöhe (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Position of the drawing origin</source>
      <translation>Lage des Zeichnungsursprungs</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Rotation (degrees clockwise from north)</source>
      <translation>Drehung (Grad im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Scale (ground metres per drawing metre)</source>
      <translation>Maßstab (Meter im Gelände je Zeichnungsmeter)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Raster resolution (m/px)</source>
      <translation>Rasterauflösung (m/px)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Widest door (m)</source>
      <translation>Breiteste Tür (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Corridor width (m)</source>
      <translation>Flurbreite (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>Flächen zusammenführen, die kleiner sind als (m²)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Parallel processes (0 = every core)</source>
      <translation>Parallele Prozesse (0 = alle Kerne)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Also merge the floors into building.osm</source>
      <translation>Die Geschosse auch zu building.osm zusammenführen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Output folder</source>
      <translation>Ausgabeordner</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Report (CSV)</source>
      <translation>Bericht (CSV)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>CSV files (*.csv)</source>
      <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floors converted</source>
      <translation>Umgewandelte Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floors that failed</source>
      <translation>Gescheiterte Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>using the placement saved in the project: {:.7f}, {:.7f}, {:.2f}°</source>
      <translation>verwende die im Projekt gespeicherte Platzierung: {:.7f}, {:.7f}, {:.2f}°</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>FOLDER: '{}' is not a folder</source>
      <translation>FOLDER: '{}' ist kein Ordner</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>no file in '{}' matches '{}': check the folder and the pattern</source>
      <translation>keine Datei in '{}' passt auf '{}': Ordner und Muster prüfen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{} files, {} parallel processes</source>
      <translation>{} Dateien, {} parallele Prozesse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>merged {} floors into {}</source>
      <translation>{} Geschosse zu {} zusammengeführt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{} of {} files failed: {}</source>
      <translation>{} von {} Dateien gescheitert: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>started {} (level {})</source>
      <translation>{} gestartet (Geschoss {})</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Canceled by the user.</source>
      <translation>Vom Benutzer abgebrochen.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>exit code {}</source>
      <translation>Exit-Code {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>the worker process ended without a result: {}</source>
      <translation>der Arbeitsprozess endete ohne Ergebnis: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{}: {} areas, {} passages in {:.1f} s -&gt; {}</source>
      <translation>{}: {} Flächen, {} Durchgänge in {:.1f} s -&gt; {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{}: failed: {}</source>
      <translation>{}: gescheitert: {}</translation>
    </message>
  </context>
  <context>
    <name>EvaluateSegmentationAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Evaluate segmentation against ground truth</source>
      <translation>Segmentierung mit der Referenz vergleichen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Tools</source>
      <translation>Werkzeuge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Compares the LABELS raster of 'Segment' (area ids, 0 = none) with a ground-truth image of the same size that paints every room in its own colour (black walls, white or grey outside). For every ground-truth room the predicted area with the largest overlap is its match: recall and precision of that match, the Matthews correlation coefficient (MCC) of the two masks over the annotated and segmented pixels (weighted by room area), and the F1 score of rooms matched one to one at IoU &gt;= 0.5.
LABELS: the area id raster written by 'Segment' (one integer per pixel).
GROUND_TRUTH: a PNG, BMP or TIFF image with exactly the raster's width and height in pixels.
MIN_ROOM_PX: ground-truth colours covering fewer pixels than this are antialiasing or labels, not rooms, and are ignored (pixels; at 0.05 m/px, 40 px are 0.1 m²).
REPORT (optional): a CSV with one row per ground-truth room (colour, pixels, matched area, recall, precision, IoU).
Outputs: MCC, F1, mean RECALL and PRECISION (0-1), the number of ground-truth rooms (GT_ROOMS), predicted areas (PREDICTED_AREAS) and rooms matched at IoU &gt;= 0.5 (MATCHED).</source>
      <translation>Vergleicht das LABELS-Raster von „Segmentieren“ (Flächenkennungen, 0 = keine) mit einem Referenzbild gleicher Größe, das jeden Raum in einer eigenen Farbe zeigt (Wände schwarz, außen weiß oder grau). Für jeden Referenzraum ist die vorhergesagte Fläche mit der größten Überlappung sein Treffer: Recall und Precision dieses Treffers, der Matthews-Korrelationskoeffizient (MCC) der beiden Masken über die annotierten und segmentierten Pixel (nach Raumfläche gewichtet) und der F1-Wert der eins zu eins bei IoU &gt;= 0.5 zugeordneten Räume.
LABELS: das von „Segmentieren“ geschriebene Flächenkennungs-Raster (eine Ganzzahl je Pixel).
GROUND_TRUTH: ein PNG-, BMP- oder TIFF-Bild mit genau der Breite und Höhe des Rasters in Pixeln.
MIN_ROOM_PX: Referenzfarben, die weniger Pixel als dieser Wert bedecken, sind Kantenglättung oder Beschriftung, keine Räume, und werden ignoriert (Pixel; bei 0.05 m/px sind 40 px 0.1 m²).
REPORT (optional): eine CSV-Datei mit einer Zeile je Referenzraum (Farbe, Pixel, zugeordnete Fläche, Recall, Precision, IoU).
Ausgaben: MCC, F1, mittlerer RECALL und mittlere PRECISION (0-1), die Anzahl der Referenzräume (GT_ROOMS), der vorhergesagten Flächen (PREDICTED_AREAS) und der bei IoU &gt;= 0.5 zugeordneten Räume (MATCHED).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Area id raster (LABELS of Segment)</source>
      <translation>Flächenkennungs-Raster (LABELS von Segmentieren)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ground-truth colour image</source>
      <translation>Farbiges Referenzbild</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ignore ground-truth colours covering fewer pixels than</source>
      <translation>Referenzfarben ignorieren, die weniger Pixel bedecken als</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Per-room report</source>
      <translation>Bericht je Raum</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>MCC (area-weighted)</source>
      <translation>MCC (flächengewichtet)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>F1 at IoU &gt;= 0.5</source>
      <translation>F1 bei IoU &gt;= 0.5</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Mean recall</source>
      <translation>Mittlerer Recall</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Mean precision</source>
      <translation>Mittlere Precision</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ground-truth rooms</source>
      <translation>Referenzräume</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Predicted areas</source>
      <translation>Vorhergesagte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Rooms matched at IoU &gt;= 0.5</source>
      <translation>Bei IoU &gt;= 0.5 zugeordnete Räume</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>LABELS: the raster cannot be opened</source>
      <translation>LABELS: Das Raster kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>GROUND_TRUTH: '{}' does not exist</source>
      <translation>GROUND_TRUTH: '{}' existiert nicht</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>{} ground-truth rooms, {} predicted areas</source>
      <translation>{} Referenzräume, {} vorhergesagte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>recall {:.3f}  precision {:.3f}  MCC {:.3f}  F1 {:.3f}</source>
      <translation>Recall {:.3f}  Precision {:.3f}  MCC {:.3f}  F1 {:.3f}</translation>
    </message>
  </context>
  <context>
    <name>ExportOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Export osmAG (.osm)</source>
      <translation>osmAG exportieren (.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Writes AREAS and PASSAGES (and optional floor/building outlines as structure areas, which become the osmAG:parent of the areas inside them) as an osmAG file: OpenStreetMap XML that JOSM, GDAL and osmium open, with one root node, negative ids, closed area ways sharing their border nodes, and passage ways whose two nodes belong to both areas they join.
Georeference: layers in a geographic or projected CRS are converted to WGS84 (the root node is placed at ANCHOR_LON/ANCHOR_LAT when given, else at the centre of the data). Layers in the CAD frame (no CRS) are placed with ANCHOR_LON/ANCHOR_LAT (where the CAD origin lies, also the root node), ROTATION and SCALE; without an anchor the export stops and asks you to georeference first.
VARIANT 'semantic' references areas by name (survives JOSM editing), 'fix-id' by way id. The file is written atomically: a failed export leaves no file behind. Holes (pillars) are not part of an osmAG area way and are left out (counted in the log).
STRUCTURE (optional): polygons of the floor or building outline, written as structure areas.
LEVEL: the level tag of every area and passage (e.g. 1, -1); empty keeps the layers' own level field, else 1. HEIGHT: height per level in metres (height tag).
ANCHOR_LON / ANCHOR_LAT in degrees (WGS84), ROTATION in degrees clockwise from north, SCALE in ground metres per CAD metre: the placement of 'Place a floor plan on the map' gives all four.
OUTPUT: the .osm file to write.
Outputs: AREA_COUNT, PASSAGE_COUNT and NODE_COUNT written; SHARED_NODES, the nodes shared by two or more areas; HOLES_DROPPED, the holes of areas left out (osmAG areas have no holes).</source>
      <translation>Schreibt AREAS und PASSAGES (und optional Geschoss-/Gebäudeumrisse als Strukturflächen, die zum osmAG:parent der Flächen darin werden) als osmAG-Datei: OpenStreetMap-XML, das JOSM, GDAL und osmium öffnen, mit einem Wurzelknoten, negativen Kennungen, geschlossenen Flächenwegen, die ihre Randknoten teilen, und Durchgangswegen, deren zwei Knoten zu beiden verbundenen Flächen gehören.
Georeferenzierung: Layer in einem geographischen oder projizierten KBS werden nach WGS84 umgerechnet (der Wurzelknoten liegt bei ANCHOR_LON/ANCHOR_LAT, falls angegeben, sonst in der Mitte der Daten). Layer im CAD-System (ohne KBS) werden mit ANCHOR_LON/ANCHOR_LAT (wo der CAD-Ursprung liegt, zugleich der Wurzelknoten), ROTATION und SCALE platziert; ohne Anker bricht der Export ab und bittet, zuerst zu georeferenzieren.
VARIANT 'semantic' verweist auf Flächen über den Namen (übersteht Bearbeitung in JOSM), 'fix-id' über die Weg-Kennung. Die Datei wird atomar geschrieben: Ein gescheiterter Export hinterlässt keine Datei. Löcher (Stützen) gehören nicht zu einem osmAG-Flächenweg und werden weggelassen (im Protokoll gezählt).
STRUCTURE (optional): Polygone des Geschoss- oder Gebäudeumrisses, als Strukturflächen geschrieben.
LEVEL: das Tag level jeder Fläche und jedes Durchgangs (z. B. 1, -1); leer übernimmt das Feld level der Layer, sonst 1. HEIGHT: Höhe je Geschoss in Metern (Tag height).
ANCHOR_LON / ANCHOR_LAT in Grad (WGS84), ROTATION in Grad im Uhrzeigersinn von Norden, SCALE in Metern im Gelände je CAD-Meter: Die Platzierung von „Einen Grundriss auf der Karte platzieren“ liefert alle vier.
OUTPUT: die zu schreibende .osm-Datei.
Ausgaben: AREA_COUNT, PASSAGE_COUNT und NODE_COUNT geschrieben; SHARED_NODES, die von zwei oder mehr Flächen geteilten Knoten; HOLES_DROPPED, die weggelassenen Löcher von Flächen (osmAG-Flächen haben keine Löcher).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Areas</source>
      <translation>Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Passages</source>
      <translation>Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Floor / building outlines (structure areas)</source>
      <translation>Geschoss-/Gebäudeumrisse (Strukturflächen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Level (empty: the areas' own level field, else 1)</source>
      <translation>Geschoss (leer: das Feld level der Flächen, sonst 1)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Height per level (m)</source>
      <translation>Höhe je Geschoss (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Variant</source>
      <translation>Variante</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>semantic (names)</source>
      <translation>semantic (Namen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>fix-id (way ids)</source>
      <translation>fix-id (Weg-Kennungen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Anchor / root longitude (CAD-frame layers: where the CAD origin lies)</source>
      <translation>Längengrad des Ankers / Wurzelknotens (Layer im CAD-System: wo der CAD-Ursprung liegt)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Anchor / root latitude</source>
      <translation>Breitengrad des Ankers / Wurzelknotens</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Rotation of CAD-frame layers (degrees clockwise from north)</source>
      <translation>Drehung der Layer im CAD-System (Grad im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Scale of CAD-frame layers</source>
      <translation>Maßstab der Layer im CAD-System</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG-Datei</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation>OpenStreetMap-XML (*.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Areas written</source>
      <translation>Geschriebene Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Passages written</source>
      <translation>Geschriebene Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Nodes written</source>
      <translation>Geschriebene Knoten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Nodes shared by 2+ areas</source>
      <translation>Von 2+ Flächen geteilte Knoten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Holes left out</source>
      <translation>Weggelassene Löcher</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation>AREAS: Der Eingabelayer kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>PASSAGES</source>
      <translation>PASSAGES</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>STRUCTURE</source>
      <translation>STRUCTURE</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>{} is in {} but AREAS is in {}; reproject it to the CRS of AREAS first</source>
      <translation>{} liegt in {}, AREAS aber in {}; zuerst in das KBS von AREAS umprojizieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS holds several levels ({}): export one level at a time (filter the layer, or set LEVEL), then combine the files with 'Merge osmAG floors into a building'</source>
      <translation>AREAS enthält mehrere Geschosse ({}): ein Geschoss nach dem anderen exportieren (den Layer filtern oder LEVEL setzen), dann die Dateien mit „osmAG-Geschosse zu einem Gebäude zusammenführen“ vereinen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>layers are in {}: converting to WGS84</source>
      <translation>Layer liegen in {}: Umrechnung nach WGS84</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS has no CRS (CAD frame): georeference the layers first (cad2osmag:georeference), or give ANCHOR_LON and ANCHOR_LAT (where the CAD origin lies) and ROTATION</source>
      <translation>AREAS hat kein KBS (CAD-System): die Layer zuerst georeferenzieren (cad2osmag:georeference) oder ANCHOR_LON und ANCHOR_LAT (wo der CAD-Ursprung liegt) und ROTATION angeben</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>CAD-frame layers placed with {}</source>
      <translation>Layer im CAD-System platziert mit {}</translation>
    </message>
  </context>
  <context>
    <name>ExtractStructureAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Extract structure from DXF/DWG</source>
      <translation>Bauteile aus DXF/DWG extrahieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Reads INPUT, a DXF floor plan or a DWG (AutoCAD R13-2018, read directly: no converter needed), explodes blocks (with scale, rotation, mirror and MINSERT arrays; entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.
LAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). LAYERS: explicit layer names (separated by ';') that override the rules. UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS is set, so that doorways stay open; door swings and door blocks (by name, in many languages) are found on any layer and written as DOORS (jamb to jamb); furniture blocks, free-standing furniture on layer 0 and pattern hatches are left out (the log counts every class).
Whole sheets: title frames, title blocks and legends are left out and the structure is grouped into plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists every group with its index, extent, title and kind (plan / detail / legend). PLAN picks another (an index, or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.
Outputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' rebuilds the geometry from them; block, class), TEXTS (points with text, height, rotation, layer, entity, block, tag = ATTRIB tag, id, hidden = on a frozen or off layer; 'Assign room names and types from texts' reads them) and DOORS (doorway lines with source and width). Figures: PLANS (the plans found on the sheet) and PLAN_COUNT (their number), DOOR_COUNT (doorways found), CLASSES (entities counted per class), UNIT and UNIT_SCALE (the unit used and metres per drawing unit), GEOMETRY_COUNT (structure features written) and TEXT_COUNT (texts written).</source>
      <translation>Liest INPUT, einen DXF-Grundriss oder eine DWG (AutoCAD R13-2018, direkt gelesen: kein Konverter nötig), löst Blöcke auf (mit Skalierung, Drehung, Spiegelung und MINSERT-Anordnungen; Objekte auf Layer 0 in einem Block übernehmen den Layer des INSERT), überspringt gefrorene und ausgeschaltete Layer, behält die von den Layer-Regeln gewählten Bauteil-Layer (Wände, Stützen, Fenster/Verglasung, Treppen, Aufzüge sowie die Referenzlayer 0 und Defpoints) und zerlegt Kurven auf 1 cm genau.
LAYER_RULES: eine JSON-Datei mit Schlüsselwörtern ohne Beachtung der Groß-/Kleinschreibung (algorithms/default_layer_rules.json kopieren). LAYERS: ausdrückliche Layernamen (durch ';' getrennt), die die Regeln ersetzen. UNITS: $INSUNITS im Dateikopf ist nur ein Hinweis; als Vorgabe wird die Einheit so gewählt, dass das Gebäude 5-500 m groß ist (eine Warnung nennt beide Einheiten). Tür-Layer werden weggelassen, außer INCLUDE_DOORS ist gesetzt, damit Türöffnungen offen bleiben; Türschwenkbögen und Türblöcke (nach Namen, in vielen Sprachen) werden auf jedem Layer gefunden und als DOORS geschrieben (von Laibung zu Laibung); Möbelblöcke, frei stehende Möbel auf Layer 0 und Musterschraffuren werden weggelassen (das Protokoll zählt jede Klasse).
Ganze Blätter: Rahmen, Schriftfelder und Legenden werden weggelassen, und die Bauteile werden in Pläne gruppiert (Gruppen, die mehr als 5 m auseinander liegen); der Hauptplan (größte Wandmasse) wird behalten, das Protokoll listet jede Gruppe mit Index, Ausdehnung, Titel und Art (Plan / Detail / Legende). PLAN wählt einen anderen (ein Index, oder xmin,ymin,xmax,ymax in Metern); PLAN_EXTENT ist dieselbe Ausdehnung, im Kartenfenster gezeichnet.
Ausgaben, in Metern im eigenen System der Zeichnung (ein lokales technisches KBS, nicht georeferenziert): WALLS (Linien mit den Feldern layer, kind, entity, closed, filled, width; „Bauteile rastern“ baut daraus die Geometrie auf; block, class), TEXTS (Punkte mit text, height, rotation, layer, entity, block, tag = ATTRIB-Tag, id, hidden = auf einem gefrorenen oder ausgeschalteten Layer; „Raumnamen und -typen aus Texten zuweisen“ liest sie) und DOORS (Türöffnungslinien mit source und width). Kennzahlen: PLANS (die auf dem Blatt gefundenen Pläne) und PLAN_COUNT (ihre Anzahl), DOOR_COUNT (gefundene Türöffnungen), CLASSES (Objekte je Klasse gezählt), UNIT und UNIT_SCALE (die verwendete Einheit und Meter je Zeichnungseinheit), GEOMETRY_COUNT (geschriebene Bauteilobjekte) und TEXT_COUNT (geschriebene Texte).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Layers to keep (';' separated, overrides the rules)</source>
      <translation>Zu behaltende Layer (durch ';' getrennt, ersetzt die Regeln)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Drawing units</source>
      <translation>Zeichnungseinheiten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>automatic (header + plausibility)</source>
      <translation>automatisch (Dateikopf + Plausibilität)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>inch</source>
      <translation>Zoll</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>feet</source>
      <translation>Fuß</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Include doors (rasterize doorways as closed)</source>
      <translation>Türen einbeziehen (Türöffnungen geschlossen rastern)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Structure lines</source>
      <translation>Bauteillinien</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Texts</source>
      <translation>Texte</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Doorways found (door swings and door blocks)</source>
      <translation>Gefundene Türöffnungen (Türschwenkbögen und Türblöcke)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Plans found on the sheet</source>
      <translation>Auf dem Blatt gefundene Pläne</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of groups found on the sheet</source>
      <translation>Anzahl der auf dem Blatt gefundenen Gruppen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of doorways found</source>
      <translation>Anzahl gefundener Türöffnungen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Entity counts per class</source>
      <translation>Objektanzahl je Klasse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Unit used</source>
      <translation>Verwendete Einheit</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Drawing units to metres</source>
      <translation>Zeichnungseinheiten in Metern</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of structure features</source>
      <translation>Anzahl der Bauteilobjekte</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of texts</source>
      <translation>Anzahl der Texte</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Entity classes: {}; {} doorways found</source>
      <translation>Objektklassen: {}; {} Türöffnungen gefunden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Sheet: {}</source>
      <translation>Blatt: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Kept {} features on layers: {}; {} texts; unit {} (header: {})</source>
      <translation>{} Objekte auf den Layern behalten: {}; {} Texte; Einheit {} (Dateikopf: {})</translation>
    </message>
  </context>
  <context>
    <name>GeoreferenceAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeference (place the plan on the map)</source>
      <translation>Georeferenzieren (Plan auf der Karte platzieren)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Transforms layers drawn in the CAD frame (metres, no CRS) into a target CRS (default WGS84).
Mode 'Anchor': pick ANCHOR on the map canvas (any CRS) for the CAD point CAD_ANCHOR_X/Y (default the drawing origin); ROTATION is the direction of the plan's +y axis in degrees clockwise from north, or give ROTATION_POINT (a second map point) for the CAD point CAD_ROTATION_X/Y and the rotation is computed from the two picked points; SCALE is ground metres per CAD metre.
Mode 'Control points': GCPS is a point layer whose geometry is each point picked against a basemap and whose fields cad_x, cad_y (or sourceX, sourceY) hold its CAD coordinates; at least 2 points, not all on one line. A least-squares similarity (Helmert) is solved and the residual of every point and their RMS are reported in metres.
FIX_SCALE keeps SCALE during the fit (solves position and rotation only).
AREAS and PASSAGES: layers in the CAD frame (metres, no CRS), e.g. the outputs of 'Refine'; OUTPUT_AREAS and OUTPUT_PASSAGES get them in TARGET_CRS (default WGS84, EPSG:4326) with all their fields. MODE chooses 'Anchor point + rotation' or 'Control points'. CAD_ANCHOR_X / CAD_ANCHOR_Y and CAD_ROTATION_X / CAD_ROTATION_Y are CAD coordinates in metres.
All conversions go through a transverse Mercator projection centred on the anchor (pyproj/PROJ), never a flat-earth approximation. Add a basemap (Vector ▸ CAD to osmAG ▸ Add … basemap) to pick points against real imagery, or drag the plan into place with Vector ▸ CAD to osmAG ▸ Place a floor plan on the map, whose placement gives ANCHOR, ROTATION and SCALE.
Outputs: RMS and RESIDUALS, the control point residuals in metres (overall and per point); FRAME, the placement as text; ANCHOR_LON and ANCHOR_LAT (degrees), ROTATION_DEG (degrees clockwise from north) and SCALE_FACTOR of the placement, to reuse for the other floors.</source>
      <translation>Überführt Layer, die im CAD-System gezeichnet sind (Meter, ohne KBS), in ein Ziel-KBS (Vorgabe WGS84).
Modus 'Ankerpunkt': ANCHOR im Kartenfenster (beliebiges KBS) für den CAD-Punkt CAD_ANCHOR_X/Y wählen (Vorgabe der Zeichnungsursprung); ROTATION ist die Richtung der +y-Achse des Plans in Grad im Uhrzeigersinn von Norden, oder ROTATION_POINT (ein zweiter Kartenpunkt) für den CAD-Punkt CAD_ROTATION_X/Y angeben, dann wird die Drehung aus den zwei gewählten Punkten berechnet; SCALE ist Meter im Gelände je CAD-Meter.
Modus 'Passpunkte': GCPS ist ein Punktlayer, dessen Geometrie jeweils der auf einer Hintergrundkarte gewählte Punkt ist und dessen Felder cad_x, cad_y (oder sourceX, sourceY) seine CAD-Koordinaten enthalten; mindestens 2 Punkte, nicht alle auf einer Geraden. Eine Ähnlichkeitstransformation (Helmert) wird nach kleinsten Quadraten gelöst, und das Residuum jedes Punktes sowie ihr RMS werden in Metern gemeldet.
FIX_SCALE hält SCALE bei der Ausgleichung fest (löst nur Lage und Drehung).
AREAS und PASSAGES: Layer im CAD-System (Meter, ohne KBS), z. B. die Ausgaben von „Verfeinern“; OUTPUT_AREAS und OUTPUT_PASSAGES erhalten sie in TARGET_CRS (Vorgabe WGS84, EPSG:4326) mit allen Feldern. MODE wählt 'Ankerpunkt + Drehung' oder 'Passpunkte'. CAD_ANCHOR_X / CAD_ANCHOR_Y und CAD_ROTATION_X / CAD_ROTATION_Y sind CAD-Koordinaten in Metern.
Alle Umrechnungen laufen über eine transversale Mercator-Projektion mit dem Anker als Mitte (pyproj/PROJ), nie über eine Flache-Erde-Näherung. Eine Hintergrundkarte hinzufügen (Vektor ▸ CAD zu osmAG ▸ … Hintergrundkarte hinzufügen), um Punkte auf echten Luftbildern zu wählen, oder den Plan mit Vektor ▸ CAD zu osmAG ▸ Einen Grundriss auf der Karte platzieren an seinen Ort ziehen; diese Platzierung liefert ANCHOR, ROTATION und SCALE.
Ausgaben: RMS und RESIDUALS, die Residuen der Passpunkte in Metern (gesamt und je Punkt); FRAME, die Platzierung als Text; ANCHOR_LON und ANCHOR_LAT (Grad), ROTATION_DEG (Grad im Uhrzeigersinn von Norden) und SCALE_FACTOR der Platzierung, zur Wiederverwendung für die anderen Geschosse.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor point + rotation</source>
      <translation>Ankerpunkt + Drehung</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points (least squares)</source>
      <translation>Passpunkte (kleinste Quadrate)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Layer in the CAD frame (areas or any)</source>
      <translation>Layer im CAD-System (Flächen oder beliebig)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Second layer in the CAD frame (passages)</source>
      <translation>Zweiter Layer im CAD-System (Durchgänge)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode</source>
      <translation>Modus</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor: where the CAD anchor point lies on the map</source>
      <translation>Anker: wo der CAD-Ankerpunkt auf der Karte liegt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD anchor point x (m)</source>
      <translation>CAD-Ankerpunkt x (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD anchor point y (m)</source>
      <translation>CAD-Ankerpunkt y (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Rotation of the plan's +y axis (degrees clockwise from north)</source>
      <translation>Drehung der +y-Achse des Plans (Grad im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Or: second map point (defines the rotation)</source>
      <translation>Oder: zweiter Kartenpunkt (legt die Drehung fest)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD x of the second point (m)</source>
      <translation>CAD-x des zweiten Punktes (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD y of the second point (m)</source>
      <translation>CAD-y des zweiten Punktes (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Scale (ground metres per CAD metre)</source>
      <translation>Maßstab (Meter im Gelände je CAD-Meter)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points (fields cad_x, cad_y)</source>
      <translation>Passpunkte (Felder cad_x, cad_y)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points: keep the scale at SCALE (solve rotation and shift only)</source>
      <translation>Passpunkte: Maßstab auf SCALE festhalten (nur Drehung und Verschiebung lösen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Target CRS</source>
      <translation>Ziel-KBS</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeferenced layer</source>
      <translation>Georeferenzierter Layer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeferenced second layer</source>
      <translation>Georeferenzierter zweiter Layer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>RMS of control point residuals (m)</source>
      <translation>RMS der Passpunkt-Residuen (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Residual per control point (m)</source>
      <translation>Residuum je Passpunkt (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor, rotation, scale of the placement</source>
      <translation>Anker, Drehung, Maßstab der Platzierung</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor longitude</source>
      <translation>Längengrad des Ankers</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor latitude</source>
      <translation>Breitengrad des Ankers</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Rotation (deg)</source>
      <translation>Drehung (Grad)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Scale</source>
      <translation>Maßstab</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode 'Control points' needs the GCPS point layer</source>
      <translation>Modus 'Passpunkte' benötigt den Punktlayer GCPS</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>GCPS needs fields with the CAD coordinates of each point: cad_x and cad_y (found: {})</source>
      <translation>GCPS benötigt Felder mit den CAD-Koordinaten jedes Punktes: cad_x und cad_y (gefunden: {})</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {} has no geometry</source>
      <translation>Passpunkt {} hat keine Geometrie</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {} has no numeric {} / {}</source>
      <translation>Passpunkt {} hat kein numerisches {} / {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>GCPS has no CRS: its points must be picked on a map</source>
      <translation>GCPS hat kein KBS: Seine Punkte müssen auf einer Karte gewählt werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {}: residual {:.4f} m</source>
      <translation>Passpunkt {}: Residuum {:.4f} m</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>RMS of residuals: {:.4f} m ({} points)</source>
      <translation>RMS der Residuen: {:.4f} m ({} Punkte)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>The control points do not fit a similarity transform well (RMS {:.2f} m, worst point {} off by {:.2f} m): check that each point's CAD x/y match where it was picked</source>
      <translation>Die Passpunkte passen schlecht zu einer Ähnlichkeitstransformation (RMS {:.2f} m, schlechtester Punkt {} um {:.2f} m daneben): prüfen, ob CAD-x/y jedes Punktes zu der Stelle passen, an der er gewählt wurde</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>The fitted scale is {:.4f} (the plan would be stretched by {:+.1%}): check the drawing units or the control points, or set FIX_SCALE</source>
      <translation>Der ausgeglichene Maßstab ist {:.4f} (der Plan würde um {:+.1%} gestreckt): die Zeichnungseinheiten oder die Passpunkte prüfen, oder FIX_SCALE setzen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode 'Anchor' needs ANCHOR: pick the point on the map canvas where the CAD anchor point lies</source>
      <translation>Modus 'Ankerpunkt' benötigt ANCHOR: im Kartenfenster den Punkt wählen, an dem der CAD-Ankerpunkt liegt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>rotation from the two picked points: {:.4f} degrees</source>
      <translation>Drehung aus den zwei gewählten Punkten: {:.4f} Grad</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>{} is already georeferenced ({}); this algorithm places layers in the CAD frame (the outputs of the segment and refine algorithms). Use 'Reproject layer' to change the CRS of a placed layer.</source>
      <translation>{} ist bereits georeferenziert ({}); dieser Algorithmus platziert Layer im CAD-System (die Ausgaben der Algorithmen Segmentieren und Verfeinern). Mit „Layer reprojizieren“ das KBS eines platzierten Layers ändern.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Canceled by the user.</source>
      <translation>Vom Benutzer abgebrochen.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>{} feature {}: {}</source>
      <translation>{} Objekt {}: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation>AREAS: Der Eingabelayer kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>placement: {}</source>
      <translation>Platzierung: {}</translation>
    </message>
  </context>
  <context>
    <name>ListLayersAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>List DXF/DWG layers</source>
      <translation>DXF/DWG-Layer auflisten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Reports every layer of INPUT, a DXF or DWG drawing (DWG: AutoCAD R13-2018, read directly), with its entity counts by type (after exploding blocks: entities on layer 0 inside a block count on the INSERT's layer), whether it is frozen or off, and whether the layer rules keep it (kind and matching keyword; door layers are listed with kind 'door' but not kept, since doorways stay open unless doors are included). Use the table to choose the LAYERS of 'Extract structure from DXF/DWG' or to write your own LAYER_RULES JSON file.
Layer names as delivered: the rules match the meaningful part of a name (the prefix of a bound external reference, as in E1-RI-1F$0$A-WALL, is ignored); the 'matched' column shows it.
LAYER_RULES: a JSON file of layer keywords (empty: the built-in rules, algorithms/default_layer_rules.json).
Outputs: OUTPUT, a table without geometry, one row per layer (save it as CSV, or keep it as a memory layer); LAYER_COUNT, the number of layers; KEPT_LAYERS, the layers the rules keep (separated by ';'); HEADER_UNIT, the unit written in the drawing's header ($INSUNITS).</source>
      <translation>Meldet jeden Layer von INPUT, einer DXF- oder DWG-Zeichnung (DWG: AutoCAD R13-2018, direkt gelesen), mit seinen Objektanzahlen je Typ (nach dem Auflösen der Blöcke: Objekte auf Layer 0 in einem Block zählen auf dem Layer des INSERT), ob er gefroren oder ausgeschaltet ist und ob die Layer-Regeln ihn behalten (Art und passendes Schlüsselwort; Tür-Layer werden mit der Art 'door' aufgeführt, aber nicht behalten, da Türöffnungen offen bleiben, außer Türen werden einbezogen). Mit der Tabelle die LAYERS von „Bauteile aus DXF/DWG extrahieren“ wählen oder eine eigene LAYER_RULES-JSON-Datei schreiben.
Layernamen wie geliefert: Die Regeln prüfen den aussagekräftigen Teil eines Namens (das Präfix einer gebundenen externen Referenz, wie in E1-RI-1F$0$A-WALL, wird ignoriert); die Spalte 'matched' zeigt ihn.
LAYER_RULES: eine JSON-Datei mit Layer-Schlüsselwörtern (leer: die eingebauten Regeln, algorithms/default_layer_rules.json).
Ausgaben: OUTPUT, eine Tabelle ohne Geometrie, eine Zeile je Layer (als CSV speichern oder als temporären Layer behalten); LAYER_COUNT, die Anzahl der Layer; KEPT_LAYERS, die von den Regeln behaltenen Layer (durch ';' getrennt); HEADER_UNIT, die im Dateikopf der Zeichnung stehende Einheit ($INSUNITS).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Layer report</source>
      <translation>Layer-Bericht</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Number of layers</source>
      <translation>Anzahl der Layer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Layers the rules keep (semicolon separated)</source>
      <translation>Von den Regeln behaltene Layer (durch Semikolon getrennt)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Unit written in the header ($INSUNITS)</source>
      <translation>Im Dateikopf stehende Einheit ($INSUNITS)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>{} layers, {} kept by the rules: {}</source>
      <translation>{} Layer, {} von den Regeln behalten: {}</translation>
    </message>
  </context>
  <context>
    <name>ListPlansAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>List the plans on a DXF/DWG sheet</source>
      <translation>Die Pläne auf einem DXF/DWG-Blatt auflisten</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, and lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON layer rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its index (the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and height in metres, metres of walls, and main = true for the plan converted by default (index 0 when it is a plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and legends left out) to draw the sheet under the rectangles; draw an extent over it to give PLAN_EXTENT. MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details). PLAN_COUNT is the number of groups and PLANS lists them as text.</source>
      <translation>Findet die Pläne auf einem ganzen Zeichnungsblatt (DXF oder DWG) wie „Bauteile aus DXF/DWG extrahieren“ und listet jede Gruppe auf, statt eine zu behalten: INPUT ist die Zeichnung, LAYER_RULES die optionalen JSON-Layer-Regeln. OUTPUT enthält ein Rechteck je Gruppe, in Metern im eigenen System der Zeichnung, mit Index (der Wert für PLAN), Art (plan, detail, legend, other), Titel (z. B. '三层平面图'), Breite und Höhe in Metern, Metern an Wänden und main = true für den Plan, der als Vorgabe umgewandelt wird (Index 0, wenn es ein Plan ist). STRUCTURE (optional) enthält die Bauteillinien des ganzen Blatts (ohne Rahmen und Legenden), um das Blatt unter den Rechtecken zu zeichnen; darüber eine Ausdehnung zeichnen, um PLAN_EXTENT anzugeben. MAIN_PLAN ist der Index des Hauptplans (-1, wenn das Blatt nur Details enthält). PLAN_COUNT ist die Anzahl der Gruppen, PLANS listet sie als Text.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Plans on the sheet</source>
      <translation>Pläne auf dem Blatt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Structure lines of the whole sheet</source>
      <translation>Bauteillinien des ganzen Blatts</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Number of groups found on the sheet</source>
      <translation>Anzahl der auf dem Blatt gefundenen Gruppen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Index of the main plan (-1: none)</source>
      <translation>Index des Hauptplans (-1: keiner)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Plans found on the sheet</source>
      <translation>Auf dem Blatt gefundene Pläne</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_plans.py" />
      <source>Sheet: {}</source>
      <translation>Blatt: {}</translation>
    </message>
  </context>
  <context>
    <name>LoadOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Load osmAG (.osm)</source>
      <translation>osmAG laden (.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Tools</source>
      <translation>Werkzeuge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Opens an osmAG file (semantic or fix-id variant; written by this plugin, JOSM or other osmAG tools) as an areas polygon layer and a passages line layer with every tag as a field (plus osm_id, and from_id / to_id resolving each passage's areas to their way ids, and vertical = yes for a passage between two stair or lift areas). Areas are coloured by osmAG:areatype, passages drawn as bold red lines and vertical passages thick blue (styles/osmag_*.qml), both labelled with their name; GeoPackage outputs keep the style. Dangling references (missing nodes, passages naming unknown areas) and unclosed area ways are reported and skipped. A file without any osmAG area is rejected.
INPUT: the osmAG file (.osm, OpenStreetMap XML, coordinates in WGS84 degrees).
TARGET_CRS: CRS of the output layers (default WGS84, EPSG:4326); choose a projected CRS in metres to measure or edit the areas.
OUTPUT_AREAS / OUTPUT_PASSAGES: the two layers (temporary, GeoPackage, …).
Outputs: the number of areas and passages loaded (AREA_COUNT, PASSAGE_COUNT), the unclosed area ways (UNCLOSED) and dangling references (DANGLING) skipped, the root node's position (ROOT_LON, ROOT_LAT, degrees) and the VARIANT detected.</source>
      <translation>Öffnet eine osmAG-Datei (Variante semantic oder fix-id; geschrieben von diesem Plugin, JOSM oder anderen osmAG-Werkzeugen) als Polygonlayer der Flächen und Linienlayer der Durchgänge, mit jedem Tag als Feld (dazu osm_id, sowie from_id / to_id, die die Flächen jedes Durchgangs in ihre Weg-Kennungen auflösen, und vertical = yes für einen Durchgang zwischen zwei Treppen- oder Aufzugsflächen). Flächen werden nach osmAG:areatype eingefärbt, Durchgänge als kräftige rote Linien und vertikale Durchgänge dick blau gezeichnet (styles/osmag_*.qml), beide mit ihrem Namen beschriftet; GeoPackage-Ausgaben behalten den Stil. Verwaiste Verweise (fehlende Knoten, Durchgänge, die unbekannte Flächen nennen) und nicht geschlossene Flächenwege werden gemeldet und übersprungen. Eine Datei ohne jede osmAG-Fläche wird abgelehnt.
INPUT: die osmAG-Datei (.osm, OpenStreetMap-XML, Koordinaten in WGS84-Grad).
TARGET_CRS: KBS der Ausgabelayer (Vorgabe WGS84, EPSG:4326); ein projiziertes KBS in Metern wählen, um die Flächen zu messen oder zu bearbeiten.
OUTPUT_AREAS / OUTPUT_PASSAGES: die zwei Layer (temporär, GeoPackage, …).
Ausgaben: die Anzahl geladener Flächen und Durchgänge (AREA_COUNT, PASSAGE_COUNT), die übersprungenen nicht geschlossenen Flächenwege (UNCLOSED) und verwaisten Verweise (DANGLING), die Lage des Wurzelknotens (ROOT_LON, ROOT_LAT, Grad) und die erkannte VARIANT.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG-Datei</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Output CRS</source>
      <translation>Ausgabe-KBS</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG areas</source>
      <translation>osmAG-Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG passages</source>
      <translation>osmAG-Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Areas loaded</source>
      <translation>Geladene Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Passages loaded</source>
      <translation>Geladene Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Unclosed area ways (skipped)</source>
      <translation>Nicht geschlossene Flächenwege (übersprungen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Dangling references (skipped)</source>
      <translation>Verwaiste Verweise (übersprungen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Root node longitude</source>
      <translation>Längengrad des Wurzelknotens</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Root node latitude</source>
      <translation>Breitengrad des Wurzelknotens</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Variant detected</source>
      <translation>Erkannte Variante</translation>
    </message>
  </context>
  <context>
    <name>MergeFloorsAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Merge osmAG floors into a building</source>
      <translation>osmAG-Geschosse zu einem Gebäude zusammenführen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Tools</source>
      <translation>Werkzeuge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Fuses floors into one osmAG building. INPUT: osmAG floor files (semantic or fix-id), and/or AREAS/PASSAGES layers (e.g. from 'Load osmAG') split by their 'level' field.
Level of each floor: LEVELS (comma-separated, in the order of the inputs), else the floor's level tags, else its file name (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: metres per level (one value for all, or one per floor; default: the floor's height tag, else 3.2).
Registration: floors drawn in different frames are moved onto each other with their stairs and lifts (areas typed stairs/elevator, or named like one): matched by name first, else by type, size and position, by consensus (one wrong match does not move a floor); rotation when two anchors agree. The log gives the residual per anchor and the RMS. Floors without anchors are registered by their outline, with a warning.
Stitching: overlapping stairs/lifts of consecutive levels get a vertical passage (a two-node way inside both shafts, tagged with the upper level and height). One building structure area is the parent of one structure area per level, which is the parent of that floor's areas; ids and names are unique across the building. Passages naming areas that do not exist are reported with their ids and left out (STRICT: stop instead). REGISTER (on by default): move the floors onto each other as above; off: keep every floor where it is. BUILDING: the building's name (the root structure area). VARIANT: the osmAG variant written: as the inputs, semantic (passages name their areas) or fix-id (passages give way ids).
Outputs: OUTPUT, one osmAG file (written atomically); optional OUTPUT_AREAS and OUTPUT_PASSAGES layers with a 'level' field; FLOOR_COUNT, VERTICAL_PASSAGES, AREA_COUNT and PASSAGE_COUNT (numbers written), RMS (registration residual in metres), DROPPED_PASSAGES (passages left out) and LEVELS_OUT (the levels, in order).</source>
      <translation>Fügt Geschosse zu einem osmAG-Gebäude zusammen. INPUT: osmAG-Geschossdateien (semantic oder fix-id) und/oder AREAS/PASSAGES-Layer (z. B. aus „osmAG laden“), nach ihrem Feld 'level' aufgeteilt.
Geschoss jeder Etage: LEVELS (durch Komma getrennt, in der Reihenfolge der Eingaben), sonst die level-Tags der Etage, sonst ihr Dateiname (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: Meter je Geschoss (ein Wert für alle oder einer je Etage; Vorgabe: das height-Tag der Etage, sonst 3.2).
Registrierung: Geschosse, die in verschiedenen Systemen gezeichnet sind, werden über ihre Treppen und Aufzüge aufeinander verschoben (Flächen vom Typ stairs/elevator oder so benannt): zuerst nach Namen zugeordnet, sonst nach Typ, Größe und Lage, im Konsens (eine falsche Zuordnung verschiebt kein Geschoss); Drehung, wenn zwei Anker übereinstimmen. Das Protokoll nennt das Residuum je Anker und den RMS. Geschosse ohne Anker werden über ihren Umriss registriert, mit einer Warnung.
Verknüpfung: Überlappende Treppen/Aufzüge aufeinanderfolgender Geschosse erhalten einen vertikalen Durchgang (ein Weg mit zwei Knoten in beiden Schächten, mit dem oberen Geschoss und der Höhe getaggt). Eine Gebäude-Strukturfläche ist die Elternfläche je einer Strukturfläche pro Geschoss, die wiederum die Elternfläche der Flächen dieses Geschosses ist; Kennungen und Namen sind im ganzen Gebäude eindeutig. Durchgänge, die nicht vorhandene Flächen nennen, werden mit ihren Kennungen gemeldet und weggelassen (STRICT: stattdessen abbrechen). REGISTER (als Vorgabe an): die Geschosse wie oben aufeinander verschieben; aus: jedes Geschoss bleibt, wo es ist. BUILDING: der Name des Gebäudes (die oberste Strukturfläche). VARIANT: die geschriebene osmAG-Variante: wie die Eingaben, semantic (Durchgänge nennen ihre Flächen beim Namen) oder fix-id (Durchgänge geben Weg-Kennungen an).
Ausgaben: OUTPUT, eine osmAG-Datei (atomar geschrieben); optionale Layer OUTPUT_AREAS und OUTPUT_PASSAGES mit einem Feld 'level'; FLOOR_COUNT, VERTICAL_PASSAGES, AREA_COUNT und PASSAGE_COUNT (geschriebene Anzahlen), RMS (Registrierungsresiduum in Metern), DROPPED_PASSAGES (weggelassene Durchgänge) und LEVELS_OUT (die Geschosse, der Reihe nach).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>osmAG floor files</source>
      <translation>osmAG-Geschossdateien</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Areas layer (several floors, 'level' field)</source>
      <translation>Flächenlayer (mehrere Geschosse, Feld 'level')</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages layer</source>
      <translation>Durchgangslayer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Levels, one per floor file (empty: level tags, else file names)</source>
      <translation>Geschosse, eines je Geschossdatei (leer: level-Tags, sonst Dateinamen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Height per level in metres (one value, or one per floor)</source>
      <translation>Höhe je Geschoss in Metern (ein Wert oder einer je Geschoss)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building name</source>
      <translation>Gebäudename</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Variant</source>
      <translation>Variante</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Register the floors on their stairs/lifts (off: keep them where they are)</source>
      <translation>Die Geschosse über ihre Treppen/Aufzüge registrieren (aus: sie bleiben, wo sie sind)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Stop on passages whose areas are missing (off: report and leave them out)</source>
      <translation>Bei Durchgängen mit fehlenden Flächen abbrechen (aus: melden und weglassen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building osmAG file</source>
      <translation>osmAG-Datei des Gebäudes</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation>OpenStreetMap-XML (*.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building areas</source>
      <translation>Flächen des Gebäudes</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building passages</source>
      <translation>Durchgänge des Gebäudes</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Floors</source>
      <translation>Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Vertical passages</source>
      <translation>Vertikale Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Areas written</source>
      <translation>Geschriebene Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages written</source>
      <translation>Geschriebene Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Registration residual RMS (m)</source>
      <translation>RMS des Registrierungsresiduums (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages left out</source>
      <translation>Weggelassene Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Levels</source>
      <translation>Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>INPUT: give at least one osmAG floor file (or an AREAS layer)</source>
      <translation>INPUT: mindestens eine osmAG-Geschossdatei angeben (oder einen AREAS-Layer)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>HEIGHTS must be numbers (metres), e.g. 3.2 or 4.5,3.2,3.2</source>
      <translation>HEIGHTS müssen Zahlen sein (Meter), z. B. 3.2 oder 4.5,3.2,3.2</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>floor file '{}' does not exist</source>
      <translation>Geschossdatei '{}' existiert nicht</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>AREAS has no CRS (CAD frame): georeference it first (cad2osmag:georeference)</source>
      <translation>AREAS hat kein KBS (CAD-System): zuerst georeferenzieren (cad2osmag:georeference)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>LEVELS gives {} levels for {} floors; give one per floor, in the order of the inputs</source>
      <translation>LEVELS nennt {} Geschosse für {} Etagen; eines je Etage angeben, in der Reihenfolge der Eingaben</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Canceled by the user.</source>
      <translation>Vom Benutzer abgebrochen.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>level {}: shift ({:.3f}, {:.3f}) m, rotation {:.3f}°, {}</source>
      <translation>Geschoss {}: Verschiebung ({:.3f}, {:.3f}) m, Drehung {:.3f}°, {}</translation>
    </message>
  </context>
  <context>
    <name>Placement</name>
    <message>
      <location filename="../ui/placement.py" />
      <source>the plan has no structure lines to show</source>
      <translation>der Plan hat keine Bauteillinien zum Anzeigen</translation>
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>Plan placement: {}</source>
      <translation>Platzierung des Plans: {}</translation>
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>the CAD to osmAG Processing provider is not loaded</source>
      <translation>der Processing-Provider „CAD zu osmAG“ ist nicht geladen</translation>
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>cannot read the structure of {}</source>
      <translation>die Bauteile von {} können nicht gelesen werden</translation>
    </message>
  </context>
  <context>
    <name>PlacementDock</name>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Load floor plan…</source>
      <translation>Grundriss laden…</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>OSM basemap</source>
      <translation>OSM-Hintergrund</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Satellite basemap</source>
      <translation>Satellitenbild</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>No plan loaded.</source>
      <translation>Kein Plan geladen.</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Move / rotate / scale</source>
      <translation>Verschieben / drehen / skalieren</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drag the plan to move it, the round handle to rotate it (Shift: whole degrees), the square handle to scale it.</source>
      <translation>Den Plan ziehen, um ihn zu verschieben, den runden Griff, um ihn zu drehen (Umschalt: ganze Grad), den quadratischen Griff, um ihn zu skalieren.</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Control points</source>
      <translation>Passpunkte</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Click a point of the drawing, then the same point on the basemap; repeat (right click cancels a half pair).</source>
      <translation>Einen Punkt der Zeichnung klicken, dann denselben Punkt auf der Hintergrundkarte; wiederholen (Rechtsklick verwirft ein halbes Paar).</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing origin longitude</source>
      <translation>Länge des Zeichnungsursprungs</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing origin latitude</source>
      <translation>Breite des Zeichnungsursprungs</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Rotation (clockwise from north)</source>
      <translation>Drehung (im Uhrzeigersinn von Norden)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Scale (ground m per drawing m)</source>
      <translation>Maßstab (Gelände-m je Zeichnungs-m)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Snap the rotation to building edges (polygon layers on the map, within 3°)</source>
      <translation>Drehung an Gebäudekanten einrasten (Polygonlayer auf der Karte, innerhalb von 3°)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Load building footprints (e.g. OpenStreetMap buildings) as a vector layer: while you turn the plan, its walls snap to their edges. Shift turns in whole degrees instead.</source>
      <translation>Gebäudegrundrisse (z. B. OpenStreetMap-Gebäude) als Vektorlayer laden: Beim Drehen des Plans rasten seine Wände an ihren Kanten ein. Umschalt dreht stattdessen in ganzen Grad.</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Control points: keep the scale (solve position and rotation only)</source>
      <translation>Passpunkte: Maßstab festhalten (nur Lage und Drehung lösen)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing x (m)</source>
      <translation>Zeichnung x (m)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing y (m)</source>
      <translation>Zeichnung y (m)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Longitude</source>
      <translation>Längengrad</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Latitude</source>
      <translation>Breitengrad</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Residual (m)</source>
      <translation>Residuum (m)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>RMS: – (add at least 2 control points)</source>
      <translation>RMS: – (mindestens 2 Passpunkte setzen)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Remove point</source>
      <translation>Punkt entfernen</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>The placement is saved with the project and used for every floor of the building.</source>
      <translation>Die Platzierung wird mit dem Projekt gespeichert und für jedes Geschoss des Gebäudes verwendet.</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Floor plan</source>
      <translation>Grundriss</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>CAD drawings (*.dxf *.dwg *.DXF *.DWG)</source>
      <translation>CAD-Zeichnungen (*.dxf *.dwg *.DXF *.DWG)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Cannot load {}: {}</source>
      <translation>{} kann nicht geladen werden: {}</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>{}: {} lines, {:.1f} × {:.1f} m</source>
      <translation>{}: {} Linien, {:.1f} × {:.1f} m</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Rotation snapped to the building edges at {:.1f}° (modulo 90°).</source>
      <translation>Drehung an den Gebäudekanten bei {:.1f}° eingerastet (modulo 90°).</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Cannot fit: {}</source>
      <translation>Anpassung nicht möglich: {}</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>RMS: {:.3f} m ({} points)</source>
      <translation>RMS: {:.3f} m ({} Punkte)</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Place the plan on the map</source>
      <translation>Plan auf der Karte platzieren</translation>
    </message>
  </context>
  <context>
    <name>RasterizeAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Rasterize structure</source>
      <translation>Bauteile rastern</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Turns structure lines (the WALLS output of 'Extract structure from DXF/DWG', or any line/polygon layer in metres) into a single-band occupancy GeoTIFF: 0 = free, 255 = occupied (the inverse of a ROS map_server image, where black is occupied). Hairlines are drawn 0.15 m wide, wide polylines with their width, filled outlines (solid hatches) filled.
The extent is the PERCENTILES (low, high) of all vertices grown to the entities that reach into them, plus PADDING (a fraction of the building size), so stray entities far away do not blow up the raster. The origin is snapped to a multiple of RESOLUTION and the geotransform maps pixels back to the drawing frame exactly.
Repair: a closing with a KERNEL x KERNEL square bridges gaps up to about 0.2 m, then an opening removes isolated specks (components that do not survive the opening and are small). STROKE: the width in metres hairlines are drawn with (0.15 m).
Multi-floor sets: give the structure layers of all floors as FLOOR_LAYERS (and/or a COMMON_EXTENT in the first floor's frame); every floor rasterized with the same values gets the same grid, pixel for pixel. Floors drawn with different origins (their extents do not overlap) are registered by cross-correlation (ALIGN_FLOORS); each raster's geotransform still maps its pixels onto its own drawing frame, so the origins differ by the floor offset but the pixels line up.
A raster above MAX_MPX megapixels stops with an error that suggests a resolution.
STAIRS_AS_OBSTACLES: draw stair and lift symbols as walls (off by default: stairs and lifts stay free space, so they become areas). DOORS (optional): doorway lines (jamb to jamb, the DOORS output of 'Extract structure') kept open even where a door layer is drawn.
Outputs: OCCUPANCY, the GeoTIFF (in the drawing frame, metres); WIDTH and HEIGHT in pixels; OCCUPIED_SHARE, the share of occupied pixels (0-1).</source>
      <translation>Wandelt Bauteillinien (die WALLS-Ausgabe von „Bauteile aus DXF/DWG extrahieren“ oder einen beliebigen Linien-/Polygonlayer in Metern) in ein einkanaliges Belegungs-GeoTIFF um: 0 = frei, 255 = belegt (die Umkehrung eines ROS-map_server-Bildes, in dem Schwarz belegt ist). Haarlinien werden 0.15 m breit gezeichnet, breite Polylinien mit ihrer Breite, gefüllte Umrisse (Volltonschraffuren) gefüllt.
Die Ausdehnung sind die PERCENTILES (unteres, oberes) aller Stützpunkte, erweitert um die Objekte, die in sie hineinreichen, plus PADDING (ein Anteil der Gebäudegröße), damit vereinzelte weit entfernte Objekte das Raster nicht aufblähen. Der Ursprung wird auf ein Vielfaches von RESOLUTION gerundet, und die Geotransformation bildet die Pixel exakt auf das System der Zeichnung ab.
Reparatur: Ein Schließen mit einem Quadrat von KERNEL x KERNEL überbrückt Lücken bis etwa 0.2 m, danach entfernt ein Öffnen vereinzelte Sprenkel (Komponenten, die das Öffnen nicht überstehen und klein sind). STROKE: die Breite in Metern, mit der Haarlinien gezeichnet werden (0.15 m).
Mehrgeschossige Sätze: die Bauteil-Layer aller Geschosse als FLOOR_LAYERS angeben (und/oder eine COMMON_EXTENT im System des ersten Geschosses); jedes mit denselben Werten gerasterte Geschoss erhält dasselbe Raster, Pixel für Pixel. Geschosse mit verschiedenen Ursprüngen (ihre Ausdehnungen überlappen nicht) werden per Kreuzkorrelation registriert (ALIGN_FLOORS); die Geotransformation jedes Rasters bildet seine Pixel weiterhin auf das eigene System der Zeichnung ab, die Ursprünge unterscheiden sich also um den Geschossversatz, aber die Pixel liegen deckungsgleich.
Ein Raster über MAX_MPX Megapixel bricht mit einer Fehlermeldung ab, die eine Auflösung vorschlägt.
STAIRS_AS_OBSTACLES: Treppen- und Aufzugssymbole als Wände zeichnen (als Vorgabe aus: Treppen und Aufzüge bleiben freier Raum und werden so zu Flächen). DOORS (optional): Türöffnungslinien (von Laibung zu Laibung, die DOORS-Ausgabe von „Bauteile extrahieren“), die offen bleiben, auch wo ein Tür-Layer gezeichnet ist.
Ausgaben: OCCUPANCY, das GeoTIFF (im System der Zeichnung, Meter); WIDTH und HEIGHT in Pixeln; OCCUPIED_SHARE, der Anteil belegter Pixel (0-1).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Structure lines</source>
      <translation>Bauteillinien</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Resolution (m/pixel)</source>
      <translation>Auflösung (m/Pixel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Padding (fraction of the building size)</source>
      <translation>Rand (Anteil der Gebäudegröße)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Vertex percentiles for the extent (low, high)</source>
      <translation>Stützpunkt-Perzentile für die Ausdehnung (unteres, oberes)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Repair kernel (pixels, 0 = no repair)</source>
      <translation>Reparaturkern (Pixel, 0 = keine Reparatur)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Width of hairlines (m)</source>
      <translation>Breite von Haarlinien (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Pixel budget (megapixels)</source>
      <translation>Pixelbudget (Megapixel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Common extent for multi-floor sets (optional)</source>
      <translation>Gemeinsame Ausdehnung für mehrgeschossige Sätze (optional)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Structure layers of all floors: rasterize on their common extent (optional)</source>
      <translation>Bauteil-Layer aller Geschosse: auf ihrer gemeinsamen Ausdehnung rastern (optional)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Register the floors (translation) before building the common grid</source>
      <translation>Die Geschosse (Verschiebung) registrieren, bevor das gemeinsame Raster gebildet wird</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>automatic (only when the floors do not overlap)</source>
      <translation>automatisch (nur wenn die Geschosse nicht überlappen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>yes</source>
      <translation>ja</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>no</source>
      <translation>nein</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Draw stair and lift symbols as obstacles</source>
      <translation>Treppen- und Aufzugssymbole als Hindernisse zeichnen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Doorways (jamb-to-jamb lines) kept open (optional)</source>
      <translation>Offen gehaltene Türöffnungen (Linien von Laibung zu Laibung, optional)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Occupancy raster</source>
      <translation>Belegungsraster</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Raster width (pixels)</source>
      <translation>Rasterbreite (Pixel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Raster height (pixels)</source>
      <translation>Rasterhöhe (Pixel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Share of occupied pixels</source>
      <translation>Anteil belegter Pixel</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>The structure layer (WALLS) could not be loaded.</source>
      <translation>Der Bauteil-Layer (WALLS) konnte nicht geladen werden.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>PERCENTILES must be two numbers such as '0.5, 99.5', got '{}'</source>
      <translation>PERCENTILES müssen zwei Zahlen wie '0.5, 99.5' sein, erhalten: '{}'</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>The structure layer is in a geographic CRS ({}); rasterize needs metres: use the WALLS output of 'Extract structure from DXF/DWG' or reproject to a projected CRS first.</source>
      <translation>Der Bauteil-Layer liegt in einem geographischen KBS ({}); das Rastern braucht Meter: die WALLS-Ausgabe von „Bauteile aus DXF/DWG extrahieren“ verwenden oder zuerst in ein projiziertes KBS umprojizieren.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>This floor is offset by ({:.3f}, {:.3f}) m from the first floor layer</source>
      <translation>Dieses Geschoss ist um ({:.3f}, {:.3f}) m gegen den Layer des ersten Geschosses versetzt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Cannot write the raster '{}': {}</source>
      <translation>Das Raster '{}' kann nicht geschrieben werden: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>{} x {} px at {} m/px, origin ({:.3f}, {:.3f}), {:.1%} occupied</source>
      <translation>{} x {} px bei {} m/px, Ursprung ({:.3f}, {:.3f}), {:.1%} belegt</translation>
    </message>
  </context>
  <context>
    <name>RefineAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refine areas (simplify, remove spikes, merge small areas)</source>
      <translation>Flächen verfeinern (vereinfachen, Spitzen entfernen, kleine Flächen zusammenführen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Makes the segmented areas light and clean while adjacent areas keep identical vertices along their shared borders. Every border between two junctions is simplified once with Douglas-Peucker (tolerance EPSILON_PX x RESOLUTION, the reported physical bound), spikes (angle below SPIKE_ANGLE, protrusion below SPIKE_LENGTH) are removed iteratively, and passage end points are locked, so each passage stays a segment whose two ends are vertices of both areas it joins. Areas smaller than MIN_AREA are merged into the neighbour they share the longest border with (stairs and elevators are kept); isolated ones are dropped. Work in metres: run it on the CAD frame (before georeferencing) or on a projected CRS.
AREAS and PASSAGES: the outputs of 'Segment' (PASSAGES optional). RESOLUTION: the raster resolution the areas were traced at, in metres per pixel. EPSILON_PX in pixels, SPIKE_ANGLE in degrees, SPIKE_LENGTH in metres, MIN_AREA in m².
Outputs: OUTPUT_AREAS and OUTPUT_PASSAGES, the refined layers; VERTICES_BEFORE, VERTICES_AFTER and VERTEX_REDUCTION (%); MAX_DEVIATION, the largest distance from the unsimplified areas (m); EPSILON_M, the tolerance in metres; AREA_COUNT and PASSAGE_COUNT written; MERGED and DROPPED small areas; COMPONENTS, the connected parts of the area graph, and LARGEST_COMPONENT_SHARE, the share of the area in the largest one.</source>
      <translation>Macht die segmentierten Flächen schlank und sauber, wobei benachbarte Flächen entlang ihrer gemeinsamen Kanten identische Stützpunkte behalten. Jede Kante zwischen zwei Knotenpunkten wird einmal mit Douglas-Peucker vereinfacht (Toleranz EPSILON_PX x RESOLUTION, die gemeldete physikalische Schranke), Spitzen (Winkel unter SPIKE_ANGLE, Überstand unter SPIKE_LENGTH) werden wiederholt entfernt, und die Endpunkte der Durchgänge sind fixiert, sodass jeder Durchgang eine Strecke bleibt, deren beide Enden Stützpunkte beider verbundenen Flächen sind. Flächen kleiner als MIN_AREA werden mit der Nachbarfläche zusammengeführt, mit der sie die längste Kante teilen (Treppen und Aufzüge bleiben erhalten); isolierte werden verworfen. In Metern arbeiten: im CAD-System (vor dem Georeferenzieren) oder in einem projizierten KBS ausführen.
AREAS und PASSAGES: die Ausgaben von „Segmentieren“ (PASSAGES optional). RESOLUTION: die Rasterauflösung, mit der die Flächen nachgezeichnet wurden, in Metern je Pixel. EPSILON_PX in Pixeln, SPIKE_ANGLE in Grad, SPIKE_LENGTH in Metern, MIN_AREA in m².
Ausgaben: OUTPUT_AREAS und OUTPUT_PASSAGES, die verfeinerten Layer; VERTICES_BEFORE, VERTICES_AFTER und VERTEX_REDUCTION (%); MAX_DEVIATION, der größte Abstand zu den unvereinfachten Flächen (m); EPSILON_M, die Toleranz in Metern; AREA_COUNT und PASSAGE_COUNT geschrieben; MERGED und DROPPED, zusammengeführte und verworfene kleine Flächen; COMPONENTS, die zusammenhängenden Teile des Flächengraphen, und LARGEST_COMPONENT_SHARE, der Flächenanteil im größten davon.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Areas</source>
      <translation>Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Passages</source>
      <translation>Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Raster resolution r the areas were traced at (m/px)</source>
      <translation>Rasterauflösung r, mit der die Flächen nachgezeichnet wurden (m/px)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Douglas-Peucker tolerance ε (pixels)</source>
      <translation>Douglas-Peucker-Toleranz ε (Pixel)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Spike angle below (degrees)</source>
      <translation>Spitzenwinkel unter (Grad)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Spike protrusion below (m)</source>
      <translation>Spitzenüberstand unter (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>Flächen zusammenführen, die kleiner sind als (m²)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refined areas</source>
      <translation>Verfeinerte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refined passages</source>
      <translation>Verfeinerte Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertices before</source>
      <translation>Stützpunkte vorher</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertices after</source>
      <translation>Stützpunkte nachher</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertex reduction (%)</source>
      <translation>Verringerung der Stützpunkte (%)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Maximum deviation from the unsimplified areas (m)</source>
      <translation>Größte Abweichung von den unvereinfachten Flächen (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Tolerance ε·r (m)</source>
      <translation>Toleranz ε·r (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Areas written</source>
      <translation>Geschriebene Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Passages written</source>
      <translation>Geschriebene Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Small areas merged</source>
      <translation>Zusammengeführte kleine Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Isolated small areas dropped</source>
      <translation>Verworfene isolierte kleine Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Connected components of the area graph</source>
      <translation>Zusammenhangskomponenten des Flächengraphen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Share of the area in the largest component</source>
      <translation>Flächenanteil in der größten Komponente</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation>AREAS: Der Eingabelayer kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>AREAS is in a geographic CRS ({}); refinement works in metres: run it on the CAD frame (before georeferencing) or reproject to a projected CRS first</source>
      <translation>AREAS liegt in einem geographischen KBS ({}); die Verfeinerung arbeitet in Metern: im CAD-System ausführen (vor dem Georeferenzieren) oder zuerst in ein projiziertes KBS umprojizieren</translation>
    </message>
  </context>
  <context>
    <name>RouteAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Plan a route on an osmAG map</source>
      <translation>Eine Route auf einer osmAG-Karte planen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Tools</source>
      <translation>Werkzeuge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Shortest route for a round robot of radius ROBOT_RADIUS (metres) over an osmAG map: INPUT, an osmAG file (ours or any other tool's, semantic or fix-id) or AREAS/PASSAGES layers (e.g. from loadosmag or refine). START and END are points picked on the canvas (any CRS) with their level (START_LEVEL/END_LEVEL, needed when floors overlap), or area names (START_NAME/END_NAME). A point up to 1 m outside the robot's free space is moved into it; farther away is an error. Passages narrower than twice the radius are closed; inside every area the route is the shortest collision-free path around its walls. Vertical passages (stairs, lifts) cost VERTICAL_COST metres per level; AVOID leaves out stairs (lifts only) or lifts and keeps the robot its radius away from them: their doorways are walls for it (a START or END inside such an area still leaves through its door). The result is a 3-D line (z = level x height) with its length, cost, levels per vertex and the areas and passages crossed. When no route exists the message names the separate parts of the map the start and the goal lie in, and the passages too narrow for the robot.
Outputs: OUTPUT, the route line; LENGTH (m) and COST (length + vertical cost, m); LEVEL_CHANGES; START_SNAP and END_SNAP, how far the start and end were moved (m); QUERY_MS, the search time in milliseconds; AREAS_CROSSED, PASSAGES_CROSSED and LEVELS (the level of every vertex).</source>
      <translation>Kürzeste Route für einen runden Roboter mit dem Radius ROBOT_RADIUS (Meter) über eine osmAG-Karte: INPUT, eine osmAG-Datei (von uns oder einem anderen Werkzeug, semantic oder fix-id) oder AREAS/PASSAGES-Layer (z. B. aus loadosmag oder refine). START und END sind im Kartenfenster gewählte Punkte (beliebiges KBS) mit ihrem Geschoss (START_LEVEL/END_LEVEL, nötig, wenn Geschosse übereinander liegen), oder Flächennamen (START_NAME/END_NAME). Ein Punkt bis 1 m außerhalb des freien Raums des Roboters wird hineingeschoben; weiter entfernt ist ein Fehler. Durchgänge schmaler als der doppelte Radius sind gesperrt; innerhalb jeder Fläche ist die Route der kürzeste kollisionsfreie Weg um ihre Wände. Vertikale Durchgänge (Treppen, Aufzüge) kosten VERTICAL_COST Meter je Geschoss; AVOID lässt Treppen (nur Aufzüge) oder Aufzüge aus und hält den Roboter um seinen Radius von ihnen fern: ihre Türöffnungen sind für ihn Wände (ein START oder END in einer solchen Fläche verlässt sie trotzdem durch ihre Tür). Das Ergebnis ist eine 3-D-Linie (z = Geschoss x Höhe) mit Länge, Kosten, Geschoss je Stützpunkt und den durchquerten Flächen und Durchgängen. Gibt es keine Route, nennt die Meldung die getrennten Teile der Karte, in denen Start und Ziel liegen, und die für den Roboter zu schmalen Durchgänge.
Ausgaben: OUTPUT, die Routenlinie; LENGTH (m) und COST (Länge + vertikale Kosten, m); LEVEL_CHANGES; START_SNAP und END_SNAP, wie weit Start und Ziel verschoben wurden (m); QUERY_MS, die Suchzeit in Millisekunden; AREAS_CROSSED, PASSAGES_CROSSED und LEVELS (das Geschoss jedes Stützpunkts).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>osmAG file (or give AREAS and PASSAGES)</source>
      <translation>osmAG-Datei (oder AREAS und PASSAGES angeben)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Areas layer (instead of the file)</source>
      <translation>Flächenlayer (statt der Datei)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Passages layer</source>
      <translation>Durchgangslayer</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start point</source>
      <translation>Startpunkt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start level</source>
      <translation>Startgeschoss</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start area name (instead of a point)</source>
      <translation>Name der Startfläche (statt eines Punktes)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End point</source>
      <translation>Zielpunkt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End level</source>
      <translation>Zielgeschoss</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End area name (instead of a point)</source>
      <translation>Name der Zielfläche (statt eines Punktes)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Robot radius (m)</source>
      <translation>Roboterradius (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Avoid</source>
      <translation>Meiden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Cost of one level of stairs or lift (m)</source>
      <translation>Kosten eines Geschosses Treppe oder Aufzug (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route</source>
      <translation>Route</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route length (m)</source>
      <translation>Routenlänge (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route cost (length + vertical cost)</source>
      <translation>Routenkosten (Länge + vertikale Kosten)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Level changes</source>
      <translation>Geschosswechsel</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start moved by (m)</source>
      <translation>Start verschoben um (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End moved by (m)</source>
      <translation>Ziel verschoben um (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Search time (ms)</source>
      <translation>Suchzeit (ms)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Areas crossed</source>
      <translation>Durchquerte Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Passages crossed</source>
      <translation>Durchquerte Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Level of every vertex</source>
      <translation>Geschoss jedes Stützpunkts</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>give an osmAG file (INPUT) or an AREAS layer (with PASSAGES)</source>
      <translation>eine osmAG-Datei (INPUT) oder einen AREAS-Layer (mit PASSAGES) angeben</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>PASSAGES is in {} but AREAS is in {}; reproject it first</source>
      <translation>PASSAGES liegt in {}, AREAS aber in {}; zuerst umprojizieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>{}: give a point or an area name ({})</source>
      <translation>{}: einen Punkt oder einen Flächennamen angeben ({})</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>route: {:.2f} m ({} level changes) through {}</source>
      <translation>Route: {:.2f} m ({} Geschosswechsel) über {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>nothing</source>
      <translation>nichts</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>stairs (wheelchairs, wheeled robots: lifts only)</source>
      <translation>Treppen (Rollstühle, Roboter auf Rädern: nur Aufzüge)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>lifts (evacuation: stairs only)</source>
      <translation>Aufzüge (Evakuierung: nur Treppen)</translation>
    </message>
  </context>
  <context>
    <name>SampleBuildingAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Generate sample building (DXF)</source>
      <translation>Beispielgebäude erzeugen (DXF)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Tools</source>
      <translation>Werkzeuge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Writes a realistic multi-floor office building as DXF files (millimetres, NCS layers, walls with real thickness, doors as blocks, glazing, a stair core and a lift, room names as TEXT, MTEXT and ATTRIB, nested blocks on layer 0, furniture and dimensions) together with a ground-truth GeoJSON per floor (rooms, doors, stair/lift anchors, in metres). The same seed always gives byte-identical files. Use it to try the pipeline or to score it.
FLOORS: number of floors (1-20), one DXF and one ground-truth file each; all floors share the stair core and the lift, so they stack.
SEED: any whole number; it varies the room layout (0 is the layout the README shows).
PREFIX: start of the file names: PREFIX-F1.dxf, PREFIX-F1.gt.geojson, …
OUTPUT_FOLDER: where the files are written (created when missing).
Outputs: FIRST_FLOOR_DXF (the first floor's DXF), DXF_FILES (every DXF, ';' separated), GROUND_TRUTH_FILES (the ground-truth GeoJSON files, ';' separated) and FLOOR_COUNT (floors written).</source>
      <translation>Schreibt ein realistisches mehrgeschossiges Bürogebäude als DXF-Dateien (Millimeter, NCS-Layer, Wände mit echter Dicke, Türen als Blöcke, Verglasung, ein Treppenhauskern und ein Aufzug, Raumnamen als TEXT, MTEXT und ATTRIB, verschachtelte Blöcke auf Layer 0, Möbel und Bemaßungen) zusammen mit einer Referenz-GeoJSON je Geschoss (Räume, Türen, Treppen-/Aufzugsanker, in Metern). Derselbe Startwert ergibt immer byte-identische Dateien. Damit die Verarbeitungskette ausprobieren oder bewerten.
FLOORS: Anzahl der Geschosse (1-20), je eine DXF- und eine Referenzdatei; alle Geschosse teilen Treppenhauskern und Aufzug, liegen also übereinander.
SEED: eine beliebige ganze Zahl; sie variiert die Raumaufteilung (0 ist die Aufteilung, die das README zeigt).
PREFIX: Anfang der Dateinamen: PREFIX-F1.dxf, PREFIX-F1.gt.geojson, …
OUTPUT_FOLDER: wohin die Dateien geschrieben werden (wird angelegt, falls nötig).
Ausgaben: FIRST_FLOOR_DXF (die DXF des ersten Geschosses), DXF_FILES (jede DXF, durch ';' getrennt), GROUND_TRUTH_FILES (die Referenz-GeoJSON-Dateien, durch ';' getrennt) und FLOOR_COUNT (geschriebene Geschosse).</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Number of floors</source>
      <translation>Anzahl der Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Random seed (layout variations)</source>
      <translation>Zufallsstartwert (Varianten der Aufteilung)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>File name prefix</source>
      <translation>Präfix der Dateinamen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Output folder</source>
      <translation>Ausgabeordner</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>DXF of the first floor</source>
      <translation>DXF des ersten Geschosses</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>All DXF files (semicolon separated)</source>
      <translation>Alle DXF-Dateien (durch Semikolon getrennt)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Ground-truth GeoJSON files (semicolon separated)</source>
      <translation>Referenz-GeoJSON-Dateien (durch Semikolon getrennt)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Number of floors written</source>
      <translation>Anzahl geschriebener Geschosse</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Wrote {}</source>
      <translation>{} geschrieben</translation>
    </message>
  </context>
  <context>
    <name>SegmentAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Segment occupancy grid into an Area Graph</source>
      <translation>Belegungsraster in einen Area Graph segmentieren</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Pipeline</source>
      <translation>Verarbeitungskette</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Area Graph segmentation (Hou et al. 2019) with the dynamic alpha of the CAD-to-osmAG method. INPUT is the output of 'Rasterize', or any occupancy grid: a GeoTIFF, a PNG/PGM image with RESOLUTION (m/px), or a ROS map.yaml (its resolution, origin, negate and thresholds are used; unknown cells are never free). Only the free space inside the building envelope is segmented: facade openings narrower than ENVELOPE_GAP are bridged, outside space is never an area; the log reports the interior area. alpha = ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 is the probe disk: spaces it sweeps through an opening are one room; door-sized narrowings that are clearly narrower than the space behind them separate rooms (this also finds rooms too narrow for the disk); corridor cells merge where nothing justifies a split; the free space is thinned to its skeleton (generalised Voronoi diagram), dead-end branches shorter than PRUNE are removed, and every skeleton edge (split at the narrowings) starts as one region. Outputs: AREAS (exact pixel-edge polygons: id, type room/corridor, area, perimeter, max clearance), PASSAGES (a segment across every opening between two areas, ends on the walls: from, to, width), LABELS (area ids on the input grid, 0 outside areas) and, when asked for, SKELETON (one line per skeleton edge: id, length, min and max clearance). Space open to the outside is still inside where there is evidence: the plan's footprint (openings up to 3 x ENVELOPE_GAP, closed at the chord between the facade wall ends, where it opens onto the interior through a doorway) and the optional TEXTS (room names, from 'Extract structure': the space holding one is never outside). FOOTPRINT: by default the footprint is used for rasters made by 'Rasterize' (CAD plans), not for images and ROS maps (robot maps, whose free space beside the rooms is where the scan ended). The optional DOORS (jamb-to-jamb lines) are kept open and become passages where the segmentation missed them. Every area has a 'component' field: its connected component in the area graph (0 = the largest); the log lists the others (rooms no passage reaches). STRUCTURE (optional): the structure lines of the drawing (WALLS of 'Extract structure'); stair and lift symbols in them type their areas stairs/elevator. TOPOLOGY_CELL (0.088 m): the skeleton, regions and merges work on cells of about this size (the largest whole multiple of the raster's cell not above it; a cell is free only when all its pixels are, so walls never open), the outlines and passages are traced on the raster's own cells; 0 = everything on the raster's cells (about twice as slow on a 0.044 m CAD raster).
Figures: AREA_COUNT, ROOM_COUNT, CORRIDOR_COUNT, PASSAGE_COUNT; INTERIOR_AREA_M2, the free area inside the building (m²); COMPONENTS and LARGEST_COMPONENT_SHARE (share of the area in the largest component); ALPHA, the probe disk in px²; SECONDS, the segmentation time.</source>
      <translation>Area-Graph-Segmentierung (Hou et al. 2019) mit dem dynamischen Alpha der CAD-to-osmAG-Methode. INPUT ist die Ausgabe von „Rastern“ oder ein beliebiges Belegungsraster: ein GeoTIFF, ein PNG/PGM-Bild mit RESOLUTION (m/px) oder eine ROS-map.yaml (deren resolution, origin, negate und Schwellwerte verwendet werden; unbekannte Zellen sind nie frei). Nur der freie Raum innerhalb der Gebäudehülle wird segmentiert: Fassadenöffnungen schmaler als ENVELOPE_GAP werden überbrückt, der Außenraum ist nie eine Fläche; das Protokoll meldet die Innenfläche. alpha = ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 ist die Prüfscheibe: Räume, die sie durch eine Öffnung hindurch überstreicht, sind ein Raum; türgroße Engstellen, die deutlich schmaler sind als der Raum dahinter, trennen Räume (so werden auch Räume gefunden, die für die Scheibe zu schmal sind); Flurzellen werden zusammengeführt, wo nichts eine Teilung rechtfertigt; der freie Raum wird zu seinem Skelett verdünnt (verallgemeinertes Voronoi-Diagramm), Sackgassen-Äste kürzer als PRUNE werden entfernt, und jede Skelettkante (an den Engstellen geteilt) beginnt als eine Region. Ausgaben: AREAS (exakte Polygone entlang der Pixelkanten: id, type room/corridor, area, perimeter, größter Freiraum), PASSAGES (eine Strecke quer durch jede Öffnung zwischen zwei Flächen, mit den Enden an den Wänden: from, to, width), LABELS (Flächenkennungen auf dem Eingaberaster, 0 außerhalb der Flächen) und, falls gewünscht, SKELETON (eine Linie je Skelettkante: id, Länge, kleinster und größter Freiraum). Zum Außenraum offener Raum gilt trotzdem als innen, wo es Belege gibt: die Grundfläche des Plans (Öffnungen bis 3 x ENVELOPE_GAP, geschlossen an der Sehne zwischen den Enden der Fassadenwände, wo sie sich über eine Türöffnung zum Inneren öffnet) und die optionalen TEXTS (Raumnamen aus „Bauteile extrahieren“: Der Raum, der einen enthält, ist nie außen). FOOTPRINT: als Vorgabe wird die Grundfläche für von „Rastern“ erzeugte Raster (CAD-Pläne) verwendet, nicht für Bilder und ROS-Karten (Roboterkarten, deren freier Raum neben den Räumen dort ist, wo der Scan endete). Die optionalen DOORS (Linien von Laibung zu Laibung) bleiben offen und werden zu Durchgängen, wo die Segmentierung sie verfehlt hat. Jede Fläche hat ein Feld 'component': ihre Zusammenhangskomponente im Flächengraphen (0 = die größte); das Protokoll listet die übrigen (Räume, die kein Durchgang erreicht). STRUCTURE (optional): die Bauteillinien der Zeichnung (WALLS von „Bauteile extrahieren“); Treppen- und Aufzugssymbole darin geben ihren Flächen den Typ stairs/elevator. TOPOLOGY_CELL (0.088 m): Skelett, Regionen und Zusammenführungen arbeiten auf Zellen etwa dieser Größe (das größte ganze Vielfache der Rasterzelle, das sie nicht übersteigt; eine Zelle ist nur frei, wenn alle ihre Pixel es sind, Wände öffnen sich also nie), Umrisse und Durchgänge werden auf den Pixeln des Rasters selbst nachgezeichnet; 0 = alles auf den Pixeln des Rasters (auf einem CAD-Raster mit 0.044 m etwa doppelt so langsam).
Kennzahlen: AREA_COUNT, ROOM_COUNT, CORRIDOR_COUNT, PASSAGE_COUNT; INTERIOR_AREA_M2, die freie Fläche im Gebäude (m²); COMPONENTS und LARGEST_COMPONENT_SHARE (Flächenanteil in der größten Komponente); ALPHA, die Prüfscheibe in px²; SECONDS, die Dauer der Segmentierung.</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Occupancy grid (GeoTIFF, PNG/PGM, or ROS map.yaml)</source>
      <translation>Belegungsraster (GeoTIFF, PNG/PGM oder ROS-map.yaml)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Resolution of a plain image (m/px; 0 = from the raster)</source>
      <translation>Auflösung eines einfachen Bildes (m/px; 0 = aus dem Raster)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Widest door (m)</source>
      <translation>Breiteste Tür (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Narrowest corridor (m)</source>
      <translation>Schmalster Flur (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Delta δ added to the width (m)</source>
      <translation>Zuschlag δ zur Breite (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Prune Voronoi branches shorter than (m)</source>
      <translation>Voronoi-Äste kürzer als (m) entfernen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Bridge facade openings up to (m)</source>
      <translation>Fassadenöffnungen überbrücken bis (m)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Cell size of the skeleton and merges (m; 0 = the raster's cells)</source>
      <translation>Zellgröße von Skelett und Zusammenführungen (m; 0 = die Zellen des Rasters)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Structure lines of the drawing (WALLS of 'Extract structure'), to recognise stairs and lifts</source>
      <translation>Bauteillinien der Zeichnung (WALLS von „Bauteile extrahieren“), um Treppen und Aufzüge zu erkennen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Use the plan's footprint as evidence of inside space</source>
      <translation>Die Grundfläche des Plans als Beleg für Innenraum verwenden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>automatic (CAD rasters from 'Rasterize': yes; images and ROS maps: no)</source>
      <translation>automatisch (CAD-Raster aus „Rastern“: ja; Bilder und ROS-Karten: nein)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>yes</source>
      <translation>ja</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>no</source>
      <translation>nein</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Room names (TEXTS of 'Extract structure'): evidence of inside space</source>
      <translation>Raumnamen (TEXTS von „Bauteile extrahieren“): Beleg für Innenraum</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Doorways (jamb-to-jamb lines) kept open and made passages</source>
      <translation>Türöffnungen (Linien von Laibung zu Laibung), offen gehalten und zu Durchgängen gemacht</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Areas</source>
      <translation>Flächen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Passages</source>
      <translation>Durchgänge</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Area id raster</source>
      <translation>Flächenkennungs-Raster</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Skeleton (Voronoi graph edges)</source>
      <translation>Skelett (Kanten des Voronoi-Graphen)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Rooms</source>
      <translation>Räume</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Corridors</source>
      <translation>Flure</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Free area inside the building (m²)</source>
      <translation>Freie Fläche im Gebäude (m²)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Connected components of the area graph</source>
      <translation>Zusammenhangskomponenten des Flächengraphen</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Share of the area in the largest component</source>
      <translation>Flächenanteil in der größten Komponente</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>alpha (px²)</source>
      <translation>Alpha (px²)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Segmentation time (s)</source>
      <translation>Dauer der Segmentierung (s)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: '{}' does not exist</source>
      <translation>INPUT: '{}' existiert nicht</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: the raster cannot be opened</source>
      <translation>INPUT: Das Raster kann nicht geöffnet werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: '{}' is not a raster file on disk</source>
      <translation>INPUT: '{}' ist keine Rasterdatei auf dem Datenträger</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>RESOLUTION ignored: the GeoTIFF carries {} m/px</source>
      <translation>RESOLUTION ignoriert: Das GeoTIFF hat {} m/px</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Grid {} x {} px at {} m/px</source>
      <translation>Raster {} x {} px bei {} m/px</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} room-name points used as evidence of inside space</source>
      <translation>{} Raumnamenpunkte als Beleg für Innenraum verwendet</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Footprint evidence: {}</source>
      <translation>Beleg durch die Grundfläche: {}</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} stair/lift areas recognised from their symbols</source>
      <translation>{} Treppen-/Aufzugsflächen an ihren Symbolen erkannt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Interior free area: {:.1f} m² (of {:.1f} m² free in the raster)</source>
      <translation>Freie Innenfläche: {:.1f} m² (von {:.1f} m² frei im Raster)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Timing (s): </source>
      <translation>Laufzeiten (s): </translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Skeleton: {} nodes, {} edges, {} branches shorter than PRUNE pruned</source>
      <translation>Skelett: {} Knoten, {} Kanten, {} Äste kürzer als PRUNE entfernt</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write area {}</source>
      <translation>Fläche {} kann nicht geschrieben werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write passage {}</source>
      <translation>Durchgang {} kann nicht geschrieben werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write skeleton edge {}</source>
      <translation>Skelettkante {} kann nicht geschrieben werden</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} areas ({} rooms, {} corridors), {} passages</source>
      <translation>{} Flächen ({} Räume, {} Flure), {} Durchgänge</translation>
    </message>
  </context>
</TS>
