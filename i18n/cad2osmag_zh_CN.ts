<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
  <context>
    <name>AssignNamesAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Assign room names and types from texts</source>
      <translation>根据文字指定房间名称和类型</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Names, numbers and types the AREAS from the drawing's TEXTS (the text output of 'Extract structure from DXF', with block attributes).
Which texts are room names: configurable rules (NAME_RULES, a copy of algorithms/default_name_rules.json) classify every text as a room name, a room number (kept as ref) or ignored, with the reason (dimension, area, elevation, door/window code, axis, stair arrow, note, title, title block, furniture...), using the text itself, the layer it sits on (room-name layers such as A-ANNO-ROOM, *-SYMB-NAME, 房间; bound-xref prefixes are stripped) and its block and attribute tag. Lines of a multi-line TEXT label are joined first.
Which area: every text is scored against every area as in the CAD-to-osmAG paper (inside: 100 - 50 rho up to rho_max 0.7, then 50 - 25 (rho - 0.7); outside but within 2.2 m of the border: 40 + 30 f_size + 20 f_dist) and goes to its best area; a text inside an area belongs to it. Name and number join; an area holding two different room names is split at the narrowing between them (SPLIT, watershed of its clearance map; a corridor between them becomes its own area), else it keeps the best-placed name and lists the others in label_conflict. Duplicate names get a suffix (the room number, else (1), (2)...); areas without text get the stable id &lt;level&gt;-&lt;area id&gt;.
Types: keywords (English, Italian, Spanish, German, French, Chinese...) and codes (*-ST-* stairs, *-P1/*-OP-*/*-FG-* lifts) set type stairs/elevator/corridor/room and the Simple Indoor Tagging fields indoor and room; long, narrow unnamed areas with three or more passages become corridors.
Edit name, ref or type in the output layer to fix them: 'Export osmAG' keeps the edits and the passages follow renamed areas. TEXT_REPORT (optional) lists every label with its role, reason, area and score.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Texts (from 'Extract structure from DXF')</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Passages (optional: split areas get their passages, corridors their degree)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Level (for generated ids; empty: the areas' level field, else 1)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Name rules (JSON, empty = built-in defaults)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Split areas holding two room names at the narrowing between them</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Named areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Passages (with those of split areas)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Text report (role, reason, area of every label)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas named from the drawing</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas with a room number</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas with a generated id</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas holding several names</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Areas split</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Texts ignored</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>Room texts outside every area</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS: the input layer cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>TEXTS</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>PASSAGES</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>{} is in {} but AREAS is in {}: reproject it to the CRS of AREAS first</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>AREAS is in a geographic CRS (degrees); the scores use metres: run this on the CAD-frame layers (before georeferencing) or reproject to a projected CRS</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_assign_names.py" />
      <source>cannot write area {} to the output layer</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>Cad2OsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/base.py" />
      <source>Canceled by the user.</source>
      <translation>已被用户取消。</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagPlugin</name>
    <message>
      <location filename="../plugin.py" />
      <source>Convert a DXF floor plan to osmAG…</source>
      <translation>将 DXF 平面图转换为 osmAG…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Show the CAD to osmAG algorithms</source>
      <translation>显示 CAD 转 osmAG 算法</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Convert a floor plan…</source>
      <translation>转换平面图…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Place a floor plan on the map…</source>
      <translation>在地图上放置平面图…</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Add OpenStreetMap basemap</source>
      <translation>添加 OpenStreetMap 底图</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Add satellite imagery basemap</source>
      <translation>添加卫星影像底图</translation>
    </message>
    <message>
      <location filename="../plugin.py" />
      <source>Added basemap “{}”.</source>
      <translation>已添加底图“{}”。</translation>
    </message>
  </context>
  <context>
    <name>Cad2OsmagProvider</name>
    <message>
      <location filename="../processing_provider/provider.py" />
      <source>CAD to osmAG</source>
      <translation>CAD 转 osmAG</translation>
    </message>
  </context>
  <context>
    <name>ConvertWizard</name>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>1. Floor plans</source>
      <translation>1. 平面图</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the layers of the selected file and which ones the layer rules keep as structure.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add files…</source>
      <translation>添加文件…</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Remove</source>
      <translation>移除</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Up</source>
      <translation>上移</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Down</source>
      <translation>下移</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Layer</source>
      <translation>图层</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Kind</source>
      <translation>类型</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Kept</source>
      <translation>保留</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Entities</source>
      <translation>实体数</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Floor plans</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>CAD drawings (*.dxf *.dwg *.DXF *.DWG)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Cannot read the layers of {}.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>yes</source>
      <translation>是</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>no</source>
      <translation>否</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{}: {} layers, kept: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>2. Segmentation settings (metres)</source>
      <translation>2. 分割设置（米）</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>The defaults suit most buildings. Smaller pixels follow thin walls better but take longer.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Raster resolution</source>
      <translation>栅格分辨率</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Widest door</source>
      <translation>最宽门宽</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Corridor width</source>
      <translation>走廊宽度</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Merge areas smaller than</source>
      <translation>合并小于此面积的区域</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Level of the first floor</source>
      <translation>第一个文件的楼层</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Floor height</source>
      <translation>层高</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Preview the areas of the first floor</source>
      <translation>预览第一层的区域</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Previewing the segmentation</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Preview failed: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>canceled</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Computing…</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas, {} passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>3. Place the plan on the map</source>
      <translation>3. 在地图上放置平面图</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add a basemap, then drag the plan to its place, turn it with the round handle, or click control points (drawing point, then map point). Every floor uses this placement.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>4. Convert and export</source>
      <translation>4. 转换并导出</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>One osmAG file per floor is written to the output folder; the floors are added to the map, styled.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>…</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Output folder</source>
      <translation>输出文件夹</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Also write the merged building (building.osm)</source>
      <translation>同时写出合并后的建筑 (building.osm)</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Add the styled floors to the map</source>
      <translation>将带样式的楼层添加到地图</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Convert</source>
      <translation>转换</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Cancel</source>
      <translation>取消</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Choose an output folder first.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting floor plans to osmAG</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Converting {} floor(s)…</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Done: {} floor(s) written to {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Stopped: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>5. Names and types</source>
      <translation>5. 名称和类型</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Correct the name and the type of any area (room, corridor, stairs, elevator, structure), then save: the osmAG files are written again.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Level</source>
      <translation>楼层</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Area</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Name</source>
      <translation>名称</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Type</source>
      <translation>类型</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Save and export again</source>
      <translation>保存并重新导出</translation>
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Exporting osmAG again</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Saving {} changed areas…</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>{} areas changed; osmAG files written again.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Export failed: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/convert_wizard.py" />
      <source>Convert a floor plan to osmAG</source>
      <translation>将平面图转换为 osmAG</translation>
    </message>
  </context>
  <context>
    <name>DxfToOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Convert DXF/DWG floor plan to osmAG</source>
      <translation>将 DXF/DWG 平面图转换为 osmAG</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Runs the whole pipeline on one floor (a DXF, or a DWG of AutoCAD R13-2018 read directly): structural layers of the drawing are kept (walls, columns, glazing, stairs), rasterized, segmented into an Area Graph of rooms, corridors and the passages between them, refined (simplified polygons with shared borders) and written as an osmAG file anchored on the Earth. With NAMES (on by default) the drawing's texts name, number and type the areas (see 'Assign room names and types from texts'; NAME_RULES adapts the rules). ANCHOR is the position of the drawing origin (pick it on a basemap), ROTATION the direction of the drawing's +y axis in degrees clockwise from north. Each step is also available as its own algorithm for finer control.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>DXF or DWG floor plan</source>
      <translation>DXF 或 DWG 平面图</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Layer rules (JSON, optional)</source>
      <translation>图层规则（JSON，可选）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Drawing units</source>
      <translation>图纸单位</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Raster resolution (m/px)</source>
      <translation>栅格分辨率（米/像素）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Widest door (m)</source>
      <translation>最宽门宽（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Corridor width (m)</source>
      <translation>走廊宽度（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>合并小于此面积的区域（平方米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Close doorways (rasterize door layers)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Room names, numbers and types from the drawing's texts</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Name rules (JSON, optional)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Level</source>
      <translation>楼层</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Floor height (m)</source>
      <translation>层高（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Position of the drawing origin</source>
      <translation>图纸原点的位置</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Rotation (degrees clockwise from north)</source>
      <translation>旋转角（自正北顺时针，度）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>osmAG variant</source>
      <translation>osmAG 变体</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG 文件</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Areas (to show on the map)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Passages (to show on the map)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Preview image</source>
      <translation>预览图</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>PNG image (*.png)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Areas</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Passages</source>
      <translation>通道</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>OUTPUT: give the .osm file to write</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag.py" />
      <source>Stage times: {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>DxfToOsmagBatchAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Convert a folder of floor plans to osmAG (parallel)</source>
      <translation>将文件夹中的平面图转换为 osmAG（并行）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Converts every floor plan of FOLDER (files matching PATTERN, e.g. '*.dxf') with the whole pipeline of 'Convert DXF floor plan to osmAG', several files at once: WORKERS processes (0 = one per processor core). Each file writes OUTPUT_FOLDER/&lt;file name&gt;.osm. A file that fails (not a drawing, no walls, …) is reported with its reason and never stops the others.
FIRST_LEVEL: the level of the first file in natural name order (floor-2 before floor-10); each next file is one level up. HEIGHT: floor height in metres.
Placement, the same for every floor: ANCHOR is where the drawing origin (0, 0) lies (pick it on the map), ROTATION the direction of the drawing's +y axis in degrees clockwise from north, SCALE ground metres per drawing metre. Without ANCHOR the placement saved in the project by 'Place a floor plan on the map' is used, if any.
RESOLUTION (m/px), DOOR_WIDTH and CORRIDOR_WIDTH (m), MIN_AREA (m²): as in the single-file algorithm. MERGE also writes OUTPUT_FOLDER/building.osm with every converted floor.
REPORT: a CSV with one row per file (file, level, status, areas, passages, seconds, message).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Folder of floor plans</source>
      <translation>平面图文件夹</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>File name patterns (';' separated)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Level of the first file</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floor height (m)</source>
      <translation>层高（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Position of the drawing origin</source>
      <translation>图纸原点的位置</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Rotation (degrees clockwise from north)</source>
      <translation>旋转角（自正北顺时针，度）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Scale (ground metres per drawing metre)</source>
      <translation>比例（每图纸米对应的地面米数）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Raster resolution (m/px)</source>
      <translation>栅格分辨率（米/像素）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Widest door (m)</source>
      <translation>最宽门宽（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Corridor width (m)</source>
      <translation>走廊宽度（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>合并小于此面积的区域（平方米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Parallel processes (0 = every core)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Also merge the floors into building.osm</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Output folder</source>
      <translation>输出文件夹</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Report (CSV)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>CSV files (*.csv)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floors converted</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Floors that failed</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>using the placement saved in the project: {:.7f}, {:.7f}, {:.2f}°</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>FOLDER: '{}' is not a folder</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>no file in '{}' matches '{}': check the folder and the pattern</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{} files, {} parallel processes</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>merged {} floors into {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{} of {} files failed: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>started {} (level {})</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>Canceled by the user.</source>
      <translation>已被用户取消。</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>exit code {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>the worker process ended without a result: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{}: {} areas, {} passages in {:.1f} s -&gt; {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_dxf_to_osmag_batch.py" />
      <source>{}: failed: {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>EvaluateSegmentationAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Evaluate segmentation against ground truth</source>
      <translation>对照真值评估分割结果</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Tools</source>
      <translation>工具</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Compares the LABELS raster of 'Segment' (area ids, 0 = none) with a ground-truth image of the same size that paints every room in its own colour (black walls, white or grey outside). For every ground-truth room the predicted area with the largest overlap is its match: recall and precision of that match, the Matthews correlation coefficient (MCC) of the two masks over the annotated and segmented pixels (weighted by room area), and the F1 score of rooms matched one to one at IoU &gt;= 0.5.
LABELS: the area id raster written by 'Segment' (one integer per pixel).
GROUND_TRUTH: a PNG, BMP or TIFF image with exactly the raster's width and height in pixels.
MIN_ROOM_PX: ground-truth colours covering fewer pixels than this are antialiasing or labels, not rooms, and are ignored (pixels; at 0.05 m/px, 40 px are 0.1 m²).
REPORT (optional): a CSV with one row per ground-truth room (colour, pixels, matched area, recall, precision, IoU).
Outputs: MCC, F1, mean RECALL and PRECISION (0-1), the number of ground-truth rooms, predicted areas and rooms matched at IoU &gt;= 0.5.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Area id raster (LABELS of Segment)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ground-truth colour image</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ignore ground-truth colours covering fewer pixels than</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Per-room report</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>MCC (area-weighted)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>F1 at IoU &gt;= 0.5</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Mean recall</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Mean precision</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Ground-truth rooms</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Predicted areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>Rooms matched at IoU &gt;= 0.5</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>LABELS: the raster cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>GROUND_TRUTH: '{}' does not exist</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>{} ground-truth rooms, {} predicted areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_evaluate_segmentation.py" />
      <source>recall {:.3f}  precision {:.3f}  MCC {:.3f}  F1 {:.3f}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>ExportOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Export osmAG (.osm)</source>
      <translation>导出 osmAG (.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Writes AREAS and PASSAGES (and optional floor/building outlines as structure areas, which become the osmAG:parent of the areas inside them) as an osmAG file: OpenStreetMap XML that JOSM, GDAL and osmium open, with one root node, negative ids, closed area ways sharing their border nodes, and passage ways whose two nodes belong to both areas they join.
Georeference: layers in a geographic or projected CRS are converted to WGS84 (the root node is placed at ANCHOR_LON/ANCHOR_LAT when given, else at the centre of the data). Layers in the CAD frame (no CRS) are placed with ANCHOR_LON/ANCHOR_LAT (where the CAD origin lies, also the root node), ROTATION and SCALE; without an anchor the export stops and asks you to georeference first.
VARIANT 'semantic' references areas by name (survives JOSM editing), 'fix-id' by way id. The file is written atomically: a failed export leaves no file behind. Holes (pillars) are not part of an osmAG area way and are left out (counted in the log).
STRUCTURE (optional): polygons of the floor or building outline, written as structure areas.
LEVEL: the level tag of every area and passage (e.g. 1, -1); empty keeps the layers' own level field, else 1. HEIGHT: height per level in metres (height tag).
ANCHOR_LON / ANCHOR_LAT in degrees (WGS84), ROTATION in degrees clockwise from north, SCALE in ground metres per CAD metre: the placement of 'Place a floor plan on the map' gives all four.
OUTPUT: the .osm file to write.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Areas</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Passages</source>
      <translation>通道</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Floor / building outlines (structure areas)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Level (empty: the areas' own level field, else 1)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Height per level (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Variant</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Anchor / root longitude (CAD-frame layers: where the CAD origin lies)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Anchor / root latitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Rotation of CAD-frame layers (degrees clockwise from north)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Scale of CAD-frame layers</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG 文件</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Areas written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Passages written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Nodes written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Nodes shared by 2+ areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>Holes left out</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>PASSAGES</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>STRUCTURE</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>{} is in {} but AREAS is in {}; reproject it to the CRS of AREAS first</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS holds several levels ({}): export one level at a time (filter the layer, or set LEVEL), then combine the files with 'Merge osmAG floors into a building'</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>layers are in {}: converting to WGS84</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>AREAS has no CRS (CAD frame): georeference the layers first (cad2osmag:georeference), or give ANCHOR_LON and ANCHOR_LAT (where the CAD origin lies) and ROTATION</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_export_osmag.py" />
      <source>CAD-frame layers placed with {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>ExtractStructureAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Extract structure from DXF/DWG</source>
      <translation>从 DXF/DWG 提取建筑结构</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Reads a DXF floor plan, or a DWG (AutoCAD R13-2018, read directly: no converter needed), explodes blocks (with scale, rotation, mirror and MINSERT arrays; entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.
LAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). LAYERS: explicit layer names (separated by ';') that override the rules. UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS is set, so that doorways stay open; door swings and door blocks (by name, in many languages) are found on any layer and written as DOORS (jamb to jamb); furniture blocks, free-standing furniture on layer 0 and pattern hatches are left out (the log counts every class).
Whole sheets: title frames, title blocks and legends are left out and the structure is grouped into plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists every group with its index, extent, title and kind (plan / detail / legend). PLAN picks another (an index, or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.
Outputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' rebuilds the geometry from them; block, class), TEXTS (points with text, height, rotation, layer, entity, block, tag = ATTRIB tag, id; 'Assign room names and types from texts' reads them) and DOORS (doorway lines with source and width).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>DXF or DWG drawing</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Layer rules (JSON, empty = built-in defaults)</source>
      <translation>图层规则（JSON，留空 = 内置规则）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Layers to keep (';' separated, overrides the rules)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Drawing units</source>
      <translation>图纸单位</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>automatic (header + plausibility)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Include doors (rasterize doorways as closed)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Structure lines</source>
      <translation>结构线</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Texts</source>
      <translation>文字</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Doorways found (door swings and door blocks)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Plans found on the sheet</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of groups found on the sheet</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of doorways found</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Entity counts per class</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Unit used</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Drawing units to metres</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of structure features</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Number of texts</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Entity classes: {}; {} doorways found</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Sheet: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_extract_structure.py" />
      <source>Kept {} features on layers: {}; {} texts; unit {} (header: {})</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>GeoreferenceAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeference (place the plan on the map)</source>
      <translation>地理配准（将平面图放到地图上）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Transforms layers drawn in the CAD frame (metres, no CRS) into a target CRS (default WGS84).
Mode 'Anchor': pick ANCHOR on the map canvas (any CRS) for the CAD point CAD_ANCHOR_X/Y (default the drawing origin); ROTATION is the direction of the plan's +y axis in degrees clockwise from north, or give ROTATION_POINT (a second map point) for the CAD point CAD_ROTATION_X/Y and the rotation is computed from the two picked points; SCALE is ground metres per CAD metre.
Mode 'Control points': GCPS is a point layer whose geometry is each point picked against a basemap and whose fields cad_x, cad_y (or sourceX, sourceY) hold its CAD coordinates; at least 2 points, not all on one line. A least-squares similarity (Helmert) is solved and the residual of every point and their RMS are reported in metres.
FIX_SCALE keeps SCALE during the fit (solves position and rotation only).
AREAS and PASSAGES: layers in the CAD frame (metres, no CRS), e.g. the outputs of 'Refine'; OUTPUT_AREAS and OUTPUT_PASSAGES get them in TARGET_CRS (default WGS84, EPSG:4326) with all their fields. MODE chooses 'Anchor point + rotation' or 'Control points'. CAD_ANCHOR_X / CAD_ANCHOR_Y and CAD_ROTATION_X / CAD_ROTATION_Y are CAD coordinates in metres.
All conversions go through a transverse Mercator projection centred on the anchor (pyproj/PROJ), never a flat-earth approximation. Add a basemap (Vector ▸ CAD to osmAG ▸ Add … basemap) to pick points against real imagery, or drag the plan into place with Vector ▸ CAD to osmAG ▸ Place a floor plan on the map, whose placement gives ANCHOR, ROTATION and SCALE.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor point + rotation</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points (least squares)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Layer in the CAD frame (areas or any)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Second layer in the CAD frame (passages)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor: where the CAD anchor point lies on the map</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD anchor point x (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD anchor point y (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Rotation of the plan's +y axis (degrees clockwise from north)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Or: second map point (defines the rotation)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD x of the second point (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>CAD y of the second point (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Scale (ground metres per CAD metre)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points (fields cad_x, cad_y)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Control points: keep the scale at SCALE (solve rotation and shift only)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Target CRS</source>
      <translation>目标坐标系</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeferenced layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Georeferenced second layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>RMS of control point residuals (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Residual per control point (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor, rotation, scale of the placement</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor longitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Anchor latitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Rotation (deg)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Scale</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode 'Control points' needs the GCPS point layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>GCPS needs fields with the CAD coordinates of each point: cad_x and cad_y (found: {})</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {} has no geometry</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {} has no numeric {} / {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>GCPS has no CRS: its points must be picked on a map</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>control point {}: residual {:.4f} m</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>RMS of residuals: {:.4f} m ({} points)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>The control points do not fit a similarity transform well (RMS {:.2f} m, worst point {} off by {:.2f} m): check that each point's CAD x/y match where it was picked</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>The fitted scale is {:.4f} (the plan would be stretched by {:+.1%}): check the drawing units or the control points, or set FIX_SCALE</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Mode 'Anchor' needs ANCHOR: pick the point on the map canvas where the CAD anchor point lies</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>rotation from the two picked points: {:.4f} degrees</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>{} is already georeferenced ({}); this algorithm places layers in the CAD frame (the outputs of the segment and refine algorithms). Use 'Reproject layer' to change the CRS of a placed layer.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>Canceled by the user.</source>
      <translation>已被用户取消。</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_georeference.py" />
      <source>placement: {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>ListLayersAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>List DXF/DWG layers</source>
      <translation>列出 DXF/DWG 图层</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Reports every layer of a DXF or DWG drawing (DWG: AutoCAD R13-2018, read directly) with its entity counts by type (after exploding blocks: entities on layer 0 inside a block count on the INSERT's layer), whether it is frozen or off, and whether the layer rules keep it (kind and matching keyword; door layers are listed with kind 'door' but not kept, since doorways stay open unless doors are included). Use the table to choose the LAYERS of 'Extract structure from DXF/DWG' or to write your own LAYER_RULES JSON file.
Layer names as delivered: the rules match the meaningful part of a name (the prefix of a bound external reference, as in E1-RI-1F$0$A-WALL, is ignored); the 'matched' column shows it.
Output: a table without geometry (save it as CSV, or keep it as a memory layer).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>DXF or DWG drawing</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Layer rules (JSON, empty = built-in defaults)</source>
      <translation>图层规则（JSON，留空 = 内置规则）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Layer report</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Number of layers</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Layers the rules keep (semicolon separated)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>Unit written in the header ($INSUNITS)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_list_layers.py" />
      <source>{} layers, {} kept by the rules: {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>LoadOsmagAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Load osmAG (.osm)</source>
      <translation>加载 osmAG (.osm)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Tools</source>
      <translation>工具</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Opens an osmAG file (semantic or fix-id variant; written by this plugin, JOSM or other osmAG tools) as an areas polygon layer and a passages line layer with every tag as a field (plus osm_id, and from_id / to_id resolving each passage's areas to their way ids, and vertical = yes for a passage between two stair or lift areas). Areas are coloured by osmAG:areatype, passages drawn as bold red lines and vertical passages thick blue (styles/osmag_*.qml), both labelled with their name; GeoPackage outputs keep the style. Dangling references (missing nodes, passages naming unknown areas) and unclosed area ways are reported and skipped. A file without any osmAG area is rejected.
INPUT: the osmAG file (.osm, OpenStreetMap XML, coordinates in WGS84 degrees).
TARGET_CRS: CRS of the output layers (default WGS84, EPSG:4326); choose a projected CRS in metres to measure or edit the areas.
OUTPUT_AREAS / OUTPUT_PASSAGES: the two layers (temporary, GeoPackage, …).
Outputs: the number of areas and passages loaded and the VARIANT detected.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG file</source>
      <translation>osmAG 文件</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Output CRS</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>osmAG passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Areas loaded</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Passages loaded</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Unclosed area ways (skipped)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Dangling references (skipped)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Root node longitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Root node latitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_load_osmag.py" />
      <source>Variant detected</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>MergeFloorsAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Merge osmAG floors into a building</source>
      <translation>将 osmAG 楼层合并为建筑</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Tools</source>
      <translation>工具</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Fuses floors into one osmAG building. INPUT: osmAG floor files (semantic or fix-id), and/or AREAS/PASSAGES layers (e.g. from 'Load osmAG') split by their 'level' field.
Level of each floor: LEVELS (comma-separated, in the order of the inputs), else the floor's level tags, else its file name (*-F3*, *_L-1*, *B1*, *3F*, *三层*). HEIGHTS: metres per level (one value for all, or one per floor; default: the floor's height tag, else 3.2).
Registration: floors drawn in different frames are moved onto each other with their stairs and lifts (areas typed stairs/elevator, or named like one): matched by name first, else by type, size and position, by consensus (one wrong match does not move a floor); rotation when two anchors agree. The log gives the residual per anchor and the RMS. Floors without anchors are registered by their outline, with a warning.
Stitching: overlapping stairs/lifts of consecutive levels get a vertical passage (a two-node way inside both shafts, tagged with the upper level and height). One building structure area is the parent of one structure area per level, which is the parent of that floor's areas; ids and names are unique across the building. Passages naming areas that do not exist are reported with their ids and left out (STRICT: stop instead). Output: one osmAG file (written atomically) and optional AREAS/PASSAGES layers with a 'level' field.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>osmAG floor files</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Areas layer (several floors, 'level' field)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Levels, one per floor file (empty: level tags, else file names)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Height per level in metres (one value, or one per floor)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building name</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Variant</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Register the floors on their stairs/lifts (off: keep them where they are)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Stop on passages whose areas are missing (off: report and leave them out)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building osmAG file</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>OpenStreetMap XML (*.osm)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Building passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Floors</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Vertical passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Areas written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Registration residual RMS (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Passages left out</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Levels</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>INPUT: give at least one osmAG floor file (or an AREAS layer)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>HEIGHTS must be numbers (metres), e.g. 3.2 or 4.5,3.2,3.2</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>floor file '{}' does not exist</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>AREAS has no CRS (CAD frame): georeference it first (cad2osmag:georeference)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>LEVELS gives {} levels for {} floors; give one per floor, in the order of the inputs</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>Canceled by the user.</source>
      <translation>已被用户取消。</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_merge_floors.py" />
      <source>level {}: shift ({:.3f}, {:.3f}) m, rotation {:.3f}°, {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>Placement</name>
    <message>
      <location filename="../ui/placement.py" />
      <source>the plan has no structure lines to show</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>Plan placement: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>the CAD to osmAG Processing provider is not loaded</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement.py" />
      <source>cannot read the structure of {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>PlacementDock</name>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Load floor plan…</source>
      <translation>加载平面图…</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>OSM basemap</source>
      <translation>OSM 底图</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Satellite basemap</source>
      <translation>卫星底图</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>No plan loaded.</source>
      <translation>尚未加载平面图。</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Move / rotate / scale</source>
      <translation>移动 / 旋转 / 缩放</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drag the plan to move it, the round handle to rotate it (Shift: whole degrees), the square handle to scale it.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Control points</source>
      <translation>控制点</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Click a point of the drawing, then the same point on the basemap; repeat (right click cancels a half pair).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing origin longitude</source>
      <translation>图纸原点经度</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing origin latitude</source>
      <translation>图纸原点纬度</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Rotation (clockwise from north)</source>
      <translation>旋转角（自正北顺时针）</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Scale (ground m per drawing m)</source>
      <translation>比例（地面米/图纸米）</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Control points: keep the scale (solve position and rotation only)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing x (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Drawing y (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Longitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Latitude</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Residual (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>RMS: – (add at least 2 control points)</source>
      <translation>RMS：–（请至少添加 2 个控制点）</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Remove point</source>
      <translation>删除点</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>The placement is saved with the project and used for every floor of the building.</source>
      <translation>放置结果随项目保存，并用于建筑的每一层。</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Floor plan</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>CAD drawings (*.dxf *.dwg *.DXF *.DWG)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Cannot load {}: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>{}: {} lines, {:.1f} × {:.1f} m</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Cannot fit: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>RMS: {:.3f} m ({} points)</source>
      <translation>RMS：{:.3f} 米（{} 个点）</translation>
    </message>
    <message>
      <location filename="../ui/placement_dock.py" />
      <source>Place the plan on the map</source>
      <translation>在地图上放置平面图</translation>
    </message>
  </context>
  <context>
    <name>RasterizeAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Rasterize structure</source>
      <translation>栅格化建筑结构</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Turns structure lines (the WALLS output of 'Extract structure from DXF/DWG', or any line/polygon layer in metres) into a single-band occupancy GeoTIFF: 0 = free, 255 = occupied (the inverse of a ROS map_server image, where black is occupied). Hairlines are drawn 0.15 m wide, wide polylines with their width, filled outlines (solid hatches) filled.
The extent is the PERCENTILES (low, high) of all vertices grown to the entities that reach into them, plus PADDING (a fraction of the building size), so stray entities far away do not blow up the raster. The origin is snapped to a multiple of RESOLUTION and the geotransform maps pixels back to the drawing frame exactly.
Repair: a closing with a KERNEL x KERNEL square bridges gaps up to about 0.2 m, then an opening removes isolated specks (components that do not survive the opening and are small).
Multi-floor sets: give the structure layers of all floors as FLOOR_LAYERS (and/or a COMMON_EXTENT in the first floor's frame); every floor rasterized with the same values gets the same grid, pixel for pixel. Floors drawn with different origins (their extents do not overlap) are registered by cross-correlation (ALIGN_FLOORS); each raster's geotransform still maps its pixels onto its own drawing frame, so the origins differ by the floor offset but the pixels line up.
A raster above MAX_MPX megapixels stops with an error that suggests a resolution.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Structure lines</source>
      <translation>结构线</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Resolution (m/pixel)</source>
      <translation>分辨率（米/像素）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Padding (fraction of the building size)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Vertex percentiles for the extent (low, high)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Repair kernel (pixels, 0 = no repair)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Width of hairlines (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Pixel budget (megapixels)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Common extent for multi-floor sets (optional)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Structure layers of all floors: rasterize on their common extent (optional)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Register the floors (translation) before building the common grid</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>automatic (only when the floors do not overlap)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>yes</source>
      <translation>是</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>no</source>
      <translation>否</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Draw stair and lift symbols as obstacles</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Doorways (jamb-to-jamb lines) kept open (optional)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Occupancy raster</source>
      <translation>占用栅格</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Raster width (pixels)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Raster height (pixels)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Share of occupied pixels</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>The structure layer (WALLS) could not be loaded.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>PERCENTILES must be two numbers such as '0.5, 99.5', got '{}'</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>The structure layer is in a geographic CRS ({}); rasterize needs metres: use the WALLS output of 'Extract structure from DXF/DWG' or reproject to a projected CRS first.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>This floor is offset by ({:.3f}, {:.3f}) m from the first floor layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>Cannot write the raster '{}': {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_rasterize.py" />
      <source>{} x {} px at {} m/px, origin ({:.3f}, {:.3f}), {:.1%} occupied</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>RefineAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refine areas (simplify, remove spikes, merge small areas)</source>
      <translation>优化区域（简化、去除尖刺、合并小区域）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Makes the segmented areas light and clean while adjacent areas keep identical vertices along their shared borders. Every border between two junctions is simplified once with Douglas-Peucker (tolerance EPSILON_PX x RESOLUTION, the reported physical bound), spikes (angle below SPIKE_ANGLE, protrusion below SPIKE_LENGTH) are removed iteratively, and passage end points are locked, so each passage stays a segment whose two ends are vertices of both areas it joins. Areas smaller than MIN_AREA are merged into the neighbour they share the longest border with (stairs and elevators are kept); isolated ones are dropped. Work in metres: run it on the CAD frame (before georeferencing) or on a projected CRS.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Areas</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Passages</source>
      <translation>通道</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Raster resolution r the areas were traced at (m/px)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Douglas-Peucker tolerance ε (pixels)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Spike angle below (degrees)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Spike protrusion below (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Merge areas smaller than (m²)</source>
      <translation>合并小于此面积的区域（平方米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refined areas</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Refined passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertices before</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertices after</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Vertex reduction (%)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Maximum deviation from the unsimplified areas (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Tolerance ε·r (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Areas written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Passages written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Small areas merged</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Isolated small areas dropped</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Connected components of the area graph</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>Share of the area in the largest component</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>AREAS: the input layer cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_refine.py" />
      <source>AREAS is in a geographic CRS ({}); refinement works in metres: run it on the CAD frame (before georeferencing) or reproject to a projected CRS first</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>RouteAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Plan a route on an osmAG map</source>
      <translation>在 osmAG 地图上规划路线</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Tools</source>
      <translation>工具</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Shortest route for a round robot of radius ROBOT_RADIUS over an osmAG map: an osmAG file (ours or any other tool's, semantic or fix-id) or AREAS/PASSAGES layers (e.g. from loadosmag or refine). START and END are points picked on the canvas (any CRS) with their level (START_LEVEL/END_LEVEL, needed when floors overlap), or area names (START_NAME/END_NAME). A point up to 1 m outside the robot's free space is moved into it; farther away is an error. Passages narrower than twice the radius are closed; inside every area the route is the shortest collision-free path around its walls. Vertical passages (stairs, lifts) cost VERTICAL_COST metres per level; AVOID leaves out stairs (lifts only) or lifts. The result is a 3-D line (z = level x height) with its length, cost, levels per vertex and the areas and passages crossed. When no route exists the message names the separate parts of the map the start and the goal lie in, and the passages too narrow for the robot.</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>osmAG file (or give AREAS and PASSAGES)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Areas layer (instead of the file)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Passages layer</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start point</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start level</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start area name (instead of a point)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End point</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End level</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End area name (instead of a point)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Robot radius (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Avoid</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Cost of one level of stairs or lift (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route length (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Route cost (length + vertical cost)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Level changes</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Start moved by (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>End moved by (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Search time (ms)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Areas crossed</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Passages crossed</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>Level of every vertex</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>give an osmAG file (INPUT) or an AREAS layer (with PASSAGES)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>PASSAGES is in {} but AREAS is in {}; reproject it first</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>{}: give a point or an area name ({})</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_route.py" />
      <source>route: {:.2f} m ({} level changes) through {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>SampleBuildingAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Generate sample building (DXF)</source>
      <translation>生成示例建筑 (DXF)</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Tools</source>
      <translation>工具</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Writes a realistic multi-floor office building as DXF files (millimetres, NCS layers, walls with real thickness, doors as blocks, glazing, a stair core and a lift, room names as TEXT, MTEXT and ATTRIB, nested blocks on layer 0, furniture and dimensions) together with a ground-truth GeoJSON per floor (rooms, doors, stair/lift anchors, in metres). The same seed always gives byte-identical files. Use it to try the pipeline or to score it.
FLOORS: number of floors (1-20), one DXF and one ground-truth file each; all floors share the stair core and the lift, so they stack.
SEED: any whole number; it varies the room layout (0 is the layout the README shows).
PREFIX: start of the file names: &lt;PREFIX&gt;-F1.dxf, &lt;PREFIX&gt;-F1.gt.geojson, …
OUTPUT_FOLDER: where the files are written (created when missing).
Outputs: FIRST_FLOOR_DXF (the first floor's DXF) and DXF_FILES (every DXF, ';' separated).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Number of floors</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Random seed (layout variations)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>File name prefix</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Output folder</source>
      <translation>输出文件夹</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>DXF of the first floor</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>All DXF files (semicolon separated)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Ground-truth GeoJSON files (semicolon separated)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Number of floors written</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_sample_building.py" />
      <source>Wrote {}</source>
      <translation type="unfinished" />
    </message>
  </context>
  <context>
    <name>SegmentAlgorithm</name>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Segment occupancy grid into an Area Graph</source>
      <translation>将占用栅格分割为区域图</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Pipeline</source>
      <translation>处理流程</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Area Graph segmentation (Hou et al. 2019) with the dynamic alpha of the CAD-to-osmAG method. INPUT is the output of 'Rasterize', or any occupancy grid: a GeoTIFF, a PNG/PGM image with RESOLUTION (m/px), or a ROS map.yaml (its resolution, origin, negate and thresholds are used; unknown cells are never free). Only the free space inside the building envelope is segmented: facade openings narrower than ENVELOPE_GAP are bridged, outside space is never an area; the log reports the interior area. alpha = ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 is the probe disk: spaces it sweeps through an opening are one room; door-sized narrowings that are clearly narrower than the space behind them separate rooms (this also finds rooms too narrow for the disk); corridor cells merge where nothing justifies a split; the free space is thinned to its skeleton (generalised Voronoi diagram), dead-end branches shorter than PRUNE are removed, and every skeleton edge (split at the narrowings) starts as one region. Outputs: AREAS (exact pixel-edge polygons: id, type room/corridor, area, perimeter, max clearance), PASSAGES (a segment across every opening between two areas, ends on the walls: from, to, width), LABELS (area ids on the input grid, 0 outside areas) and, when asked for, SKELETON (one line per skeleton edge: id, length, min and max clearance). Space open to the outside is still inside where there is evidence: the plan's footprint (openings up to 3 x ENVELOPE_GAP, closed at the chord between the facade wall ends, where it opens onto the interior through a doorway) and the optional TEXTS (room names, from 'Extract structure': the space holding one is never outside). FOOTPRINT: by default the footprint is used for rasters made by 'Rasterize' (CAD plans), not for images and ROS maps (robot maps, whose free space beside the rooms is where the scan ended). The optional DOORS (jamb-to-jamb lines) are kept open and become passages where the segmentation missed them. Every area has a 'component' field: its connected component in the area graph (0 = the largest); the log lists the others (rooms no passage reaches).</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Occupancy grid (GeoTIFF, PNG/PGM, or ROS map.yaml)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Resolution of a plain image (m/px; 0 = from the raster)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Widest door (m)</source>
      <translation>最宽门宽（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Narrowest corridor (m)</source>
      <translation>最窄走廊（米）</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Delta δ added to the width (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Prune Voronoi branches shorter than (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Bridge facade openings up to (m)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Structure lines of the drawing (WALLS of 'Extract structure'), to recognise stairs and lifts</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Use the plan's footprint as evidence of inside space</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>automatic (CAD rasters from 'Rasterize': yes; images and ROS maps: no)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>yes</source>
      <translation>是</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>no</source>
      <translation>否</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Room names (TEXTS of 'Extract structure'): evidence of inside space</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Doorways (jamb-to-jamb lines) kept open and made passages</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Areas</source>
      <translation>区域</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Passages</source>
      <translation>通道</translation>
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Area id raster</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Skeleton (Voronoi graph edges)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Rooms</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Corridors</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Free area inside the building (m²)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Connected components of the area graph</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Share of the area in the largest component</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>alpha (px²)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Segmentation time (s)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: '{}' does not exist</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: the raster cannot be opened</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>INPUT: '{}' is not a raster file on disk</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>RESOLUTION ignored: the GeoTIFF carries {} m/px</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Grid {} x {} px at {} m/px</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} room-name points used as evidence of inside space</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Footprint evidence: {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} stair/lift areas recognised from their symbols</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Interior free area: {:.1f} m² (of {:.1f} m² free in the raster)</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Timing (s): </source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>Skeleton: {} nodes, {} edges, {} branches shorter than PRUNE pruned</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write area {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write passage {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>cannot write skeleton edge {}</source>
      <translation type="unfinished" />
    </message>
    <message>
      <location filename="../processing_provider/alg_segment.py" />
      <source>{} areas ({} rooms, {} corridors), {} passages</source>
      <translation type="unfinished" />
    </message>
  </context>
</TS>
