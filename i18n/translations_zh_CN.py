"""Simplified Chinese translations of cad2osmag, keyed by the English source text (``update_ts.py`` reads
them).

Terms: area = 区域, passage = 通道, floor plan = 平面图, level = 楼层, stairs = 楼梯, lift/elevator = 电梯,
corridor = 走廊, doorway = 门洞, control points = 控制点, CRS = 坐标系, basemap = 底图.
Parameter ids (INPUT, LEVEL, …), field names and tag values stay English; keep {} placeholders in order
(Python's format fills them by position). A key may also be ``("Context", "source")``.
"""

T = {
    # --- Cad2OsmagPlugin
    "Convert a DXF floor plan to osmAG…": "将 DXF 平面图转换为 osmAG…",
    "Show the CAD to osmAG algorithms": "显示 CAD 转 osmAG 算法",
    "Convert a floor plan…": "转换平面图…",
    "Place a floor plan on the map…": "在地图上放置平面图…",
    "Add OpenStreetMap basemap": "添加 OpenStreetMap 底图",
    "Add satellite imagery basemap": "添加卫星影像底图",
    "Added basemap “{}”.": "已添加底图“{}”。",
    # --- AssignNamesAlgorithm
    "Assign room names and types from texts": "根据文字指定房间名称和类型",
    "Pipeline": "处理流程",
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
        ("根据图纸的 TEXTS（“从 DXF 提取建筑结构”输出的文字，含块属性）为 AREAS（区域）命名、编号并指定类型"
         "。\n"
         "哪些文字是房间名称：可配置的规则（NAME_RULES，algorithms/default_name_rules.json 的副本）将每段文"
         "字归为房间名称、房间编号（保存为 ref）或忽略，并给出原因（尺寸标注、面积、标高、门窗编号、轴线、楼"
         "梯箭头、注释、标题、图签、家具……），依据是文字本身、所在图层（房间名称图层，如 A-ANNO-ROOM、"
         "*-SYMB-NAME、房间；绑定外部参照的前缀会被去除）以及所属块和属性标记。多行 TEXT 标注的各行先合并。"
         "\n"
         "归属哪个区域：按 CAD-to-osmAG 论文的方法，每段文字对每个区域打分（在区域内：100 - 50 rho，直到 "
         "rho_max 0.7，之后 50 - 25 (rho - 0.7)；在区域外但距边界不超过 2.2 m：40 + 30 f_size + 20 f_dist）"
         "，并归入得分最高的区域；位于区域内部的文字属于该区域。名称与编号合并；含有两个不同房间名称的区域在"
         "二者之间的收窄处被拆分（SPLIT，从其净空图的核心区域生长；二者之间的走廊成为单独的区域），否则保留位置"
         "最佳的名称，其余名称列在 label_conflict 中。重复的名称会加上后缀（房间编号，否则为 (1)、(2)……）；"
         "没有文字的区域获得稳定的标识“楼层-区域标识”（如 2-17）。\n"
         "类型：关键词（英语、意大利语、西班牙语、德语、法语、中文……）和编码（*-ST-* 楼梯，"
         "*-P1/*-OP-*/*-FG-* 电梯）设定类型 stairs/elevator/corridor/room 以及 Simple Indoor Tagging 字段 "
         "indoor 和 room；细长、未命名且有三个或更多通道的区域成为走廊。\n"
         "如需更正，在输出图层中编辑 name、ref 或 type：“导出 osmAG”会保留这些修改，通道也会跟随改名后的区域"
         "。TEXT_REPORT（可选）列出每个标注的角色、原因、区域和得分。\n"
         "PASSAGES（可选）：区域的通道；被拆分的区域获得各自的通道，走廊按其通道数量识别。LEVEL：生成标识所"
         "用的楼层（留空：区域的 level 字段，否则为 1）。\n"
         "输出：OUTPUT_AREAS，已命名的区域（字段 name、ref、type、indoor、room、label_conflict）；"
         "OUTPUT_PASSAGES，通道，含被拆分区域的通道；计数 NAMED（根据图纸命名的区域）、NUMBERED（有房间编号"
         "）、AUTO_IDS（使用生成标识）、CONFLICTS（含多个名称）、SPLITS（被拆分的区域）、IGNORED（被忽略的文"
         "字）和 OUTSIDE（位于所有区域之外的房间文字）。"),
    "Areas": "区域",
    "Texts (from 'Extract structure from DXF')": "文字（来自“从 DXF 提取建筑结构”）",
    "Passages (optional: split areas get their passages, corridors their degree)":
        "通道（可选：拆分的区域获得其通道，走廊获得其连接度）",
    "Level (for generated ids; empty: the areas' level field, else 1)":
        "楼层（用于生成标识；留空：区域的 level 字段，否则为 1）",
    "Name rules (JSON, empty = built-in defaults)": "名称规则（JSON，留空 = 内置规则）",
    "Split areas holding two room names at the narrowing between them": "在两个房间名称之间的收窄处拆分区域",
    "Named areas": "已命名的区域",
    "Passages (with those of split areas)": "通道（含拆分区域的通道）",
    "Text report (role, reason, area of every label)": "文字报告（每个标注的角色、原因、区域）",
    "Areas named from the drawing": "根据图纸命名的区域",
    "Areas with a room number": "有房间编号的区域",
    "Areas with a generated id": "使用生成标识的区域",
    "Areas holding several names": "含多个名称的区域",
    "Areas split": "被拆分的区域",
    "Texts ignored": "被忽略的文字",
    "Room texts outside every area": "位于所有区域之外的房间文字",
    "AREAS: the input layer cannot be opened": "AREAS：无法打开输入图层",
    "TEXTS: the input layer cannot be opened": "TEXTS：无法打开输入图层",
    "TEXTS": "TEXTS",
    "PASSAGES": "PASSAGES",
    "{} is in {} but AREAS is in {}: reproject it to the CRS of AREAS first":
        "{} 位于 {}，但 AREAS 位于 {}：请先将其重投影到 AREAS 的坐标系",
    ("AREAS is in a geographic CRS (degrees); the scores use metres: run this on the CAD-frame layers "
     "(before georeferencing) or reproject to a projected CRS"):
        ("AREAS 采用地理坐标系（度）；打分以米为单位：请在 CAD 坐标系下的图层上运行（地理配准之前），或重投"
         "影到投影坐标系"),
    "cannot write area {} to the output layer": "无法将区域 {} 写入输出图层",
    # --- DxfToOsmagAlgorithm
    "Convert DXF/DWG floor plan to osmAG": "将 DXF/DWG 平面图转换为 osmAG",
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
        ("对一个楼层运行完整的处理流程（DXF，或直接读取的 AutoCAD R13-2018 DWG）：保留图纸的结构图层（墙、柱"
         "、玻璃、楼梯），栅格化，分割为由房间、走廊及其间通道组成的区域图（Area Graph），优化（共享边界的简"
         "化多边形），并写出锚定在地球上的 osmAG 文件。每一步也可作为单独的算法运行，以便更精细地控制。\n"
         "INPUT：平面图（.dxf 或 .dwg）。LAYER_RULES：图层关键词的 JSON 文件（留空：内置规则；参见“列出 "
         "DXF/DWG 图层”）。UNITS：图纸的绘图单位（auto：从文件头读取，并按合理的建筑尺寸校验）。\n"
         "RESOLUTION：栅格像素大小，单位米（默认 0.044 m；越小越能贴合薄墙，但速度越慢）。TOPOLOGY_CELL：分割的骨架与合并所用的单元大小（米；0.088 m，即两个栅格像素；轮廓保留栅格像素；0 = 栅格像素，较慢）。DOOR_WIDTH：最宽的"
         "门，单位米（2.8 m）：更窄的开口将房间分开。CORRIDOR_WIDTH：走廊宽度，单位米（8 m）。MIN_AREA：小于"
         "此面积（m²）的区域并入相邻区域（楼梯和电梯保留）。INCLUDE_DOORS：将门图层作为墙绘制（门洞封闭；默"
         "认关闭，使门洞保持开放）。\n"
         "PLAN / PLAN_EXTENT：图幅上有多个平面图时选用哪一个（留空：主平面图；日志中平面图列表的序号，或以米"
         "为单位的 xmin,ymin,xmax,ymax，或在地图画布上绘制的范围）。\n"
         "NAMES（默认开启）：用图纸中的文字为区域命名、编号并指定类型（参见“根据文字指定房间名称和类型”）；"
         "NAME_RULES：调整这些规则的 JSON 文件。\n"
         "LEVEL：该楼层的楼层号（osmAG 的 level 标签，如 1、-1）。HEIGHT：层高，单位米（3.2 m）。ANCHOR：图"
         "纸原点 (0, 0) 在地图上的位置（在底图上拾取；留空：经度 0、纬度 0）。ROTATION：图纸 +y 轴的方向，自"
         "正北顺时针的度数。VARIANT：semantic（通道按名称引用区域）或 fix-id（通道给出 way 标识）。\n"
         "输出：OUTPUT，osmAG 文件（.osm）；OUTPUT_AREAS 和 OUTPUT_PASSAGES，相同的区域和通道，作为 WGS84 图"
         "层显示在地图上；PREVIEW，可选的区域 PNG 预览图；AREA_COUNT 和 PASSAGE_COUNT，写出的数量。"),
    "DXF or DWG floor plan": "DXF 或 DWG 平面图",
    "Layer rules (JSON, optional)": "图层规则（JSON，可选）",
    "Drawing units": "图纸单位",
    "Raster resolution (m/px)": "栅格分辨率（米/像素）",
    "Widest door (m)": "最宽门宽（米）",
    "Corridor width (m)": "走廊宽度（米）",
    "Merge areas smaller than (m²)": "合并小于此面积的区域（平方米）",
    "Close doorways (rasterize door layers)": "封闭门洞（栅格化门图层）",
    "Room names, numbers and types from the drawing's texts": "根据图纸文字确定房间名称、编号和类型",
    "Name rules (JSON, optional)": "名称规则（JSON，可选）",
    "Level": "楼层",
    "Floor height (m)": "层高（米）",
    "Position of the drawing origin": "图纸原点的位置",
    "Rotation (degrees clockwise from north)": "旋转角（自正北顺时针，度）",
    "osmAG variant": "osmAG 变体",
    "osmAG file": "osmAG 文件",
    "OpenStreetMap XML (*.osm)": "OpenStreetMap XML (*.osm)",
    "Areas (to show on the map)": "区域（显示在地图上）",
    "Passages (to show on the map)": "通道（显示在地图上）",
    "Preview image": "预览图",
    "PNG image (*.png)": "PNG 图像 (*.png)",
    "Passages": "通道",
    "OUTPUT: give the .osm file to write": "OUTPUT：请指定要写出的 .osm 文件",
    "Stage times: {}": "各阶段耗时：{}",
    "auto": "自动",
    "mm": "毫米",
    "cm": "厘米",
    "m": "米",
    "inch": "英寸",
    "feet": "英尺",
    # --- DxfToOsmagBatchAlgorithm
    "Convert a folder of floor plans to osmAG (parallel)": "将文件夹中的平面图转换为 osmAG（并行）",
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
        ("用“将 DXF 平面图转换为 osmAG”的完整流程转换 FOLDER 中的每个平面图（匹配 PATTERN 的文件，如 '*.dxf'"
         "），同时处理多个文件：WORKERS 个进程（0 = 每个处理器核心一个）。每个文件写出 "
         "OUTPUT_FOLDER/NAME.osm（NAME：图纸的文件名）。失败的文件（不是图纸、没有墙……）会连同原因一起报告，"
         "绝不会中断其他文件。\n"
         "FIRST_LEVEL：按自然名称顺序（floor-2 在 floor-10 之前）第一个文件的楼层；之后每个文件高一层。"
         "HEIGHT：层高，单位米。\n"
         "放置方式，所有楼层相同：ANCHOR 为图纸原点 (0, 0) 所在位置（在地图上拾取），ROTATION 为图纸 +y 轴的"
         "方向，自正北顺时针的度数，SCALE 为每图纸米对应的地面米数。未给出 ANCHOR 时，使用“在地图上放置平面"
         "图”保存在项目中的放置结果（如有）。\n"
         "RESOLUTION（米/像素）、DOOR_WIDTH 和 CORRIDOR_WIDTH（米）、MIN_AREA（m²）：与单文件算法相同。"
         "MERGE 还会写出包含所有已转换楼层的 OUTPUT_FOLDER/building.osm。\n"
         "REPORT：CSV 文件，每个文件一行（文件、楼层、状态、区域、通道、秒数、消息）。\n"
         "输出：SUCCEEDED 和 FAILED，转换成功和失败的楼层数（一个坏文件绝不会中断其他文件），以及 "
         "OUTPUT_FOLDER。"),
    "Folder of floor plans": "平面图文件夹",
    "File name patterns (';' separated)": "文件名模式（以 ';' 分隔）",
    "Level of the first file": "第一个文件的楼层",
    "Scale (ground metres per drawing metre)": "比例（每图纸米对应的地面米数）",
    "Parallel processes (0 = every core)": "并行进程数（0 = 所有核心）",
    "Also merge the floors into building.osm": "同时将各楼层合并为 building.osm",
    "Output folder": "输出文件夹",
    "Report (CSV)": "报告（CSV）",
    "CSV files (*.csv)": "CSV 文件 (*.csv)",
    "Floors converted": "已转换的楼层",
    "Floors that failed": "转换失败的楼层",
    "using the placement saved in the project: {:.7f}, {:.7f}, {:.2f}°":
        "使用项目中保存的放置结果：{:.7f}, {:.7f}, {:.2f}°",
    "FOLDER: '{}' is not a folder": "FOLDER：'{}' 不是文件夹",
    "no file in '{}' matches '{}': check the folder and the pattern":
        "'{}' 中没有文件匹配 '{}'：请检查文件夹和模式",
    "{} files, {} parallel processes": "{} 个文件，{} 个并行进程",
    "merged {} floors into {}": "已将 {} 个楼层合并到 {}",
    "{} of {} files failed: {}": "{} 个文件失败（共 {} 个）：{}",
    "started {} (level {})": "已开始 {}（楼层 {}）",
    "Canceled by the user.": "已被用户取消。",
    "exit code {}": "退出码 {}",
    "the worker process ended without a result: {}": "工作进程结束但没有结果：{}",
    "{}: {} areas, {} passages in {:.1f} s -> {}": "{}：{} 个区域，{} 个通道，用时 {:.1f} s -> {}",
    "{}: failed: {}": "{}：失败：{}",
    # --- EvaluateSegmentationAlgorithm
    "Evaluate segmentation against ground truth": "对照真值评估分割结果",
    "Tools": "工具",
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
        ("将“分割”输出的 LABELS 栅格（区域标识，0 = 无）与同样大小的真值图像进行比较，真值图像中每个房间涂成"
         "各自的颜色（墙为黑色，室外为白色或灰色）。对每个真值房间，重叠最大的预测区域为其匹配：该匹配的召回"
         "率和精确率、两个掩膜在已标注和已分割像素上的 Matthews 相关系数（MCC，按房间面积加权），以及在 IoU "
         ">= 0.5 下一一匹配的房间的 F1 分数。\n"
         "LABELS：“分割”写出的区域标识栅格（每像素一个整数）。\n"
         "GROUND_TRUTH：PNG、BMP 或 TIFF 图像，宽度和高度（像素）须与栅格完全相同。\n"
         "MIN_ROOM_PX：覆盖像素少于此值的真值颜色是抗锯齿或标注，不是房间，将被忽略（像素；在 0.05 m/px 下，"
         "40 px 为 0.1 m²）。\n"
         "REPORT（可选）：CSV 文件，每个真值房间一行（颜色、像素、匹配的区域、召回率、精确率、IoU）。\n"
         "输出：MCC、F1、平均 RECALL 和 PRECISION（0-1），真值房间数（GT_ROOMS）、预测区域数（"
         "PREDICTED_AREAS）以及在 IoU >= 0.5 下匹配的房间数（MATCHED）。"),
    "Area id raster (LABELS of Segment)": "区域标识栅格（“分割”的 LABELS）",
    "Ground-truth colour image": "真值彩色图像",
    "Ignore ground-truth colours covering fewer pixels than": "忽略覆盖像素少于此值的真值颜色",
    "Per-room report": "逐房间报告",
    "MCC (area-weighted)": "MCC（面积加权）",
    "F1 at IoU >= 0.5": "IoU >= 0.5 时的 F1",
    "Mean recall": "平均召回率",
    "Mean precision": "平均精确率",
    "Ground-truth rooms": "真值房间",
    "Predicted areas": "预测区域",
    "Rooms matched at IoU >= 0.5": "在 IoU >= 0.5 下匹配的房间",
    "LABELS: the raster cannot be opened": "LABELS：无法打开栅格",
    "GROUND_TRUTH: '{}' does not exist": "GROUND_TRUTH：'{}' 不存在",
    "{} ground-truth rooms, {} predicted areas": "{} 个真值房间，{} 个预测区域",
    "recall {:.3f}  precision {:.3f}  MCC {:.3f}  F1 {:.3f}":
        "召回率 {:.3f}  精确率 {:.3f}  MCC {:.3f}  F1 {:.3f}",
    # --- ExportOsmagAlgorithm
    "Export osmAG (.osm)": "导出 osmAG (.osm)",
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
        ("将 AREAS 和 PASSAGES（以及可选的楼层/建筑轮廓，作为结构区域，成为其内部区域的 osmAG:parent）写为 "
         "osmAG 文件：JOSM、GDAL 和 osmium 可打开的 OpenStreetMap XML，含一个根节点、负数标识、共享边界节点"
         "的闭合区域 way，以及两个节点同时属于其连接的两个区域的通道 way。\n"
         "地理配准：地理或投影坐标系中的图层转换为 WGS84（如给出 ANCHOR_LON/ANCHOR_LAT，根节点位于该处，否则"
         "位于数据中心）。CAD 坐标系（无坐标系）中的图层用 ANCHOR_LON/ANCHOR_LAT（CAD 原点所在位置，同时也是"
         "根节点）、ROTATION 和 SCALE 放置；没有锚点时导出会停止，并提示先进行地理配准。\n"
         "VARIANT 'semantic' 按名称引用区域（经 JOSM 编辑后仍然有效），'fix-id' 按 way 标识引用。文件以原子"
         "方式写出：导出失败不会留下文件。孔洞（柱子）不属于 osmAG 区域 way，会被舍弃（在日志中计数）。\n"
         "STRUCTURE（可选）：楼层或建筑轮廓多边形，写为结构区域。\n"
         "LEVEL：每个区域和通道的 level 标签（如 1、-1）；留空则保留图层自身的 level 字段，否则为 1。HEIGHT"
         "：每层高度，单位米（height 标签）。\n"
         "ANCHOR_LON / ANCHOR_LAT 以度为单位（WGS84），ROTATION 为自正北顺时针的度数，SCALE 为每 CAD 米对应"
         "的地面米数：“在地图上放置平面图”的放置结果给出这四个值。\n"
         "OUTPUT：要写出的 .osm 文件。\n"
         "输出：写出的 AREA_COUNT、PASSAGE_COUNT 和 NODE_COUNT；SHARED_NODES，被两个或更多区域共享的节点数；"
         "HOLES_DROPPED，被舍弃的区域孔洞数（osmAG 区域没有孔洞）。"),
    "Floor / building outlines (structure areas)": "楼层/建筑轮廓（结构区域）",
    "Level (empty: the areas' own level field, else 1)": "楼层（留空：区域自身的 level 字段，否则为 1）",
    "Height per level (m)": "每层高度（米）",
    "Variant": "变体",
    "semantic (names)": "semantic（名称）",
    "fix-id (way ids)": "fix-id（way 标识）",
    "Anchor / root longitude (CAD-frame layers: where the CAD origin lies)":
        "锚点/根节点经度（CAD 坐标系图层：CAD 原点所在位置）",
    "Anchor / root latitude": "锚点/根节点纬度",
    "Rotation of CAD-frame layers (degrees clockwise from north)": "CAD 坐标系图层的旋转角（自正北顺时针，度）",
    "Scale of CAD-frame layers": "CAD 坐标系图层的比例",
    "Areas written": "已写出的区域",
    "Passages written": "已写出的通道",
    "Nodes written": "已写出的节点",
    "Nodes shared by 2+ areas": "被 2 个以上区域共享的节点",
    "Holes left out": "舍弃的孔洞",
    "STRUCTURE": "STRUCTURE",
    "{} is in {} but AREAS is in {}; reproject it to the CRS of AREAS first":
        "{} 位于 {}，但 AREAS 位于 {}；请先将其重投影到 AREAS 的坐标系",
    ("AREAS holds several levels ({}): export one level at a time (filter the layer, or set LEVEL), then "
     "combine the files with 'Merge osmAG floors into a building'"):
        ("AREAS 包含多个楼层（{}）：请逐层导出（筛选图层或设置 LEVEL），然后用“将 osmAG 楼层合并为建筑”合并"
         "这些文件"),
    "layers are in {}: converting to WGS84": "图层位于 {}：正在转换为 WGS84",
    ("AREAS has no CRS (CAD frame): georeference the layers first (cad2osmag:georeference), or give "
     "ANCHOR_LON and ANCHOR_LAT (where the CAD origin lies) and ROTATION"):
        ("AREAS 没有坐标系（CAD 坐标系）：请先对图层进行地理配准（cad2osmag:georeference），或给出 "
         "ANCHOR_LON 和 ANCHOR_LAT（CAD 原点所在位置）以及 ROTATION"),
    "CAD-frame layers placed with {}": "CAD 坐标系图层的放置方式：{}",
    # --- Cad2OsmagAlgorithm
    "Plan on the sheet (empty = main plan; an index of the log's plan list, or xmin,ymin,xmax,ymax in metres)":
        "图幅上的平面图（留空 = 主平面图；日志中平面图列表的序号，或以米为单位的 xmin,ymin,xmax,ymax）",
    "Plan extent (drawn on the canvas over the extracted structure; wins over PLAN)":
        "平面图范围（在地图画布上、于提取的结构之上绘制；优先于 PLAN）",
    # --- ExtractStructureAlgorithm
    "Extract structure from DXF/DWG": "从 DXF/DWG 提取建筑结构",
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
        ("读取 INPUT，即 DXF 平面图或 DWG（AutoCAD R13-2018，直接读取：无需转换器），分解块（含缩放、旋转、"
         "镜像和 MINSERT 阵列；块内 0 图层上的实体采用 INSERT 的图层），跳过冻结和关闭的图层，保留图层规则选"
         "出的结构图层（墙、柱、窗/玻璃、楼梯、电梯，以及参考图层 0 和 Defpoints），并以 1 cm 精度将曲线折线"
         "化。\n"
         "LAYER_RULES：不区分大小写的关键词 JSON 文件（复制 algorithms/default_layer_rules.json）。LAYERS："
         "显式的图层名称（以 ';' 分隔），优先于规则。UNITS：文件头中的 $INSUNITS 仅作参考；默认选择使建筑尺"
         "寸为 5-500 m 的单位（警告中会给出两种单位）。除非设置 INCLUDE_DOORS，门图层将被排除，使门洞保持开"
         "放；门的开启弧线和门块（按名称，支持多种语言）会在任意图层上被识别，并写为 DOORS（门垛到门垛）；家"
         "具块、0 图层上的独立家具和图案填充会被排除（日志统计每一类）。\n"
         "整张图幅：图框、图签和图例会被排除，结构按平面图分组（相距超过 5 m 的组）；保留主平面图（墙体最多"
         "的一组），日志列出每组的序号、范围、标题和种类（平面图 / 详图 / 图例）。PLAN 选择其他平面图（序号"
         "，或以米为单位的 xmin,ymin,xmax,ymax）；PLAN_EXTENT 为在地图画布上绘制的同样范围。\n"
         "输出，以米为单位、位于图纸自身坐标系中（局部工程坐标系，未地理配准）：WALLS（线，字段 layer、kind"
         "、entity、closed、filled、width；“栅格化建筑结构”据此重建几何；block、class）、TEXTS（点，字段 "
         "text、height、rotation、layer、entity、block、tag = ATTRIB 标记、id；“根据文字指定房间名称和类型”"
         "读取它们）和 DOORS（门洞线，字段 source 和 width）。统计值：PLANS（图幅上找到的平面图）和 "
         "PLAN_COUNT（其数量）、DOOR_COUNT（找到的门洞）、CLASSES（按类统计的实体数）、UNIT 和 UNIT_SCALE（"
         "所用单位及每图纸单位对应的米数）、GEOMETRY_COUNT（写出的结构要素数）和 TEXT_COUNT（写出的文字数）"
         "。"),
    "DXF or DWG drawing": "DXF 或 DWG 图纸",
    "Layer rules (JSON, empty = built-in defaults)": "图层规则（JSON，留空 = 内置规则）",
    "Layers to keep (';' separated, overrides the rules)": "要保留的图层（以 ';' 分隔，优先于规则）",
    "automatic (header + plausibility)": "自动（文件头 + 合理性检查）",
    "Include doors (rasterize doorways as closed)": "包含门（将门洞栅格化为封闭）",
    "Structure lines": "结构线",
    "Texts": "文字",
    "Doorways found (door swings and door blocks)": "找到的门洞（门的开启弧线和门块）",
    "Plans found on the sheet": "图幅上找到的平面图",
    "Number of groups found on the sheet": "图幅上找到的组数",
    "Number of doorways found": "找到的门洞数",
    "Entity counts per class": "各类实体数量",
    "Unit used": "所用单位",
    "Drawing units to metres": "图纸单位换算为米",
    "Number of structure features": "结构要素数",
    "Number of texts": "文字数",
    "Entity classes: {}; {} doorways found": "实体类别：{}；找到 {} 个门洞",
    "Sheet: {}": "图幅：{}",
    "Kept {} features on layers: {}; {} texts; unit {} (header: {})":
        "保留了 {} 个要素，所在图层：{}；{} 段文字；单位 {}（文件头：{}）",
    # --- Cad2OsmagAlgorithm
    "the point {}, {} [{}] cannot be converted to longitude/latitude: {}":
        "点 {}, {} [{}] 无法转换为经纬度：{}",
    # --- GeoreferenceAlgorithm
    "Georeference (place the plan on the map)": "地理配准（将平面图放到地图上）",
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
        ("将在 CAD 坐标系中绘制的图层（米，无坐标系）转换到目标坐标系（默认 WGS84）。\n"
         "“锚点”模式：在地图画布上（任意坐标系）为 CAD 点 CAD_ANCHOR_X/Y（默认为图纸原点）拾取 ANCHOR；"
         "ROTATION 为平面图 +y 轴的方向，自正北顺时针的度数，或为 CAD 点 CAD_ROTATION_X/Y 给出 "
         "ROTATION_POINT（第二个地图点），由两个拾取点计算旋转角；SCALE 为每 CAD 米对应的地面米数。\n"
         "“控制点”模式：GCPS 为点图层，其几何为在底图上拾取的各点，字段 cad_x、cad_y（或 sourceX、sourceY）"
         "保存其 CAD 坐标；至少 2 个点，且不全在一条直线上。以最小二乘法求解相似变换（Helmert），并以米为单"
         "位报告每个点的残差及其 RMS。\n"
         "FIX_SCALE 在拟合时保持 SCALE 不变（只求解位置和旋转）。\n"
         "AREAS 和 PASSAGES：CAD 坐标系中的图层（米，无坐标系），如“优化”的输出；OUTPUT_AREAS 和 "
         "OUTPUT_PASSAGES 以 TARGET_CRS（默认 WGS84，EPSG:4326）得到它们，保留全部字段。MODE 选择“锚点 + 旋"
         "转”或“控制点”。CAD_ANCHOR_X / CAD_ANCHOR_Y 和 CAD_ROTATION_X / CAD_ROTATION_Y 为以米为单位的 CAD "
         "坐标。\n"
         "所有转换都通过以锚点为中心的横轴墨卡托投影（pyproj/PROJ）进行，绝不使用平面地球近似。添加底图（矢"
         "量 ▸ CAD 转 osmAG ▸ 添加……底图）以便对照真实影像拾取点，或用 矢量 ▸ CAD 转 osmAG ▸ 在地图上放置平"
         "面图 将平面图拖到位置上，其放置结果给出 ANCHOR、ROTATION 和 SCALE。\n"
         "输出：RMS 和 RESIDUALS，控制点残差，单位米（总体和逐点）；FRAME，放置结果的文字描述；ANCHOR_LON 和"
         " ANCHOR_LAT（度）、ROTATION_DEG（自正北顺时针的度数）和 SCALE_FACTOR，可在其他楼层重复使用。"),
    "Anchor point + rotation": "锚点 + 旋转",
    "Control points (least squares)": "控制点（最小二乘）",
    "Layer in the CAD frame (areas or any)": "CAD 坐标系中的图层（区域或任意图层）",
    "Second layer in the CAD frame (passages)": "CAD 坐标系中的第二个图层（通道）",
    "Mode": "模式",
    "Anchor: where the CAD anchor point lies on the map": "锚点：CAD 锚点在地图上的位置",
    "CAD anchor point x (m)": "CAD 锚点 x（米）",
    "CAD anchor point y (m)": "CAD 锚点 y（米）",
    "Rotation of the plan's +y axis (degrees clockwise from north)": "平面图 +y 轴的旋转角（自正北顺时针，度）",
    "Or: second map point (defines the rotation)": "或：第二个地图点（确定旋转角）",
    "CAD x of the second point (m)": "第二个点的 CAD x（米）",
    "CAD y of the second point (m)": "第二个点的 CAD y（米）",
    "Scale (ground metres per CAD metre)": "比例（每 CAD 米对应的地面米数）",
    "Control points (fields cad_x, cad_y)": "控制点（字段 cad_x、cad_y）",
    "Control points: keep the scale at SCALE (solve rotation and shift only)":
        "控制点：将比例固定为 SCALE（只求解旋转和平移）",
    "Target CRS": "目标坐标系",
    "Georeferenced layer": "已地理配准的图层",
    "Georeferenced second layer": "已地理配准的第二个图层",
    "RMS of control point residuals (m)": "控制点残差的 RMS（米）",
    "Residual per control point (m)": "每个控制点的残差（米）",
    "Anchor, rotation, scale of the placement": "放置结果的锚点、旋转角和比例",
    "Anchor longitude": "锚点经度",
    "Anchor latitude": "锚点纬度",
    "Rotation (deg)": "旋转角（度）",
    "Scale": "比例",
    "Mode 'Control points' needs the GCPS point layer": "“控制点”模式需要 GCPS 点图层",
    "GCPS needs fields with the CAD coordinates of each point: cad_x and cad_y (found: {})":
        "GCPS 需要保存每个点 CAD 坐标的字段：cad_x 和 cad_y（找到的字段：{}）",
    "control point {} has no geometry": "控制点 {} 没有几何",
    "control point {} has no numeric {} / {}": "控制点 {} 没有数值型的 {} / {}",
    "GCPS has no CRS: its points must be picked on a map": "GCPS 没有坐标系：其点必须在地图上拾取",
    "control point {}: residual {:.4f} m": "控制点 {}：残差 {:.4f} m",
    "RMS of residuals: {:.4f} m ({} points)": "残差的 RMS：{:.4f} m（{} 个点）",
    ("The control points do not fit a similarity transform well (RMS {:.2f} m, worst point {} off by {:.2f} "
     "m): check that each point's CAD x/y match where it was picked"):
        ("控制点与相似变换拟合不佳（RMS {:.2f} m，最差的点 {} 偏差 {:.2f} m）：请检查每个点的 CAD x/y 是否与"
         "其拾取位置一致"),
    ("The fitted scale is {:.4f} (the plan would be stretched by {:+.1%}): check the drawing units or the "
     "control points, or set FIX_SCALE"):
        "拟合得到的比例为 {:.4f}（平面图将被拉伸 {:+.1%}）：请检查图纸单位或控制点，或设置 FIX_SCALE",
    "Mode 'Anchor' needs ANCHOR: pick the point on the map canvas where the CAD anchor point lies":
        "“锚点”模式需要 ANCHOR：请在地图画布上拾取 CAD 锚点所在的位置",
    "rotation from the two picked points: {:.4f} degrees": "由两个拾取点得到的旋转角：{:.4f} 度",
    ("{} is already georeferenced ({}); this algorithm places layers in the CAD frame (the outputs of the "
     "segment and refine algorithms). Use 'Reproject layer' to change the CRS of a placed layer."):
        ("{} 已经过地理配准（{}）；本算法用于放置 CAD 坐标系中的图层（分割和优化算法的输出）。要更改已放置图"
         "层的坐标系，请使用“重投影图层”。"),
    "{} feature {}: {}": "{} 要素 {}：{}",
    "placement: {}": "放置结果：{}",
    # --- ListLayersAlgorithm
    "List DXF/DWG layers": "列出 DXF/DWG 图层",
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
        ("报告 INPUT（DXF 或 DWG 图纸；DWG：AutoCAD R13-2018，直接读取）的每个图层，包括按类型统计的实体数（"
         "分解块之后：块内 0 图层上的实体计入 INSERT 的图层）、是否冻结或关闭，以及图层规则是否保留它（种类"
         "和匹配的关键词；门图层列为种类 'door' 但不保留，因为除非包含门，门洞保持开放）。可用此表选择“从 "
         "DXF/DWG 提取建筑结构”的 LAYERS，或编写自己的 LAYER_RULES JSON 文件。\n"
         "图层名称保持原样：规则匹配名称中有意义的部分（绑定外部参照的前缀，如 E1-RI-1F$0$A-WALL 中的前缀，"
         "会被忽略）；'matched' 列显示该部分。\n"
         "LAYER_RULES：图层关键词的 JSON 文件（留空：内置规则，algorithms/default_layer_rules.json）。\n"
         "输出：OUTPUT，无几何的表格，每个图层一行（可另存为 CSV，或保留为临时图层）；LAYER_COUNT，图层数；"
         "KEPT_LAYERS，规则保留的图层（以 ';' 分隔）；HEADER_UNIT，图纸文件头中记录的单位（$INSUNITS）。"),
    "Layer report": "图层报告",
    "Number of layers": "图层数",
    "Layers the rules keep (semicolon separated)": "规则保留的图层（以分号分隔）",
    "Unit written in the header ($INSUNITS)": "文件头中记录的单位（$INSUNITS）",
    "{} layers, {} kept by the rules: {}": "{} 个图层，规则保留 {} 个：{}",
    # --- Cad2OsmagAlgorithm
    "style not stored in {}: {}": "样式未保存到 {}：{}",
    "cannot convert to {}: {}": "无法转换到 {}：{}",
    "unclosed area ways (skipped): {}": "未闭合的区域 way（已跳过）：{}",
    "dangling references (skipped): nodes {} refs {}": "悬空引用（已跳过）：节点 {} 引用 {}",
    # --- LoadOsmagAlgorithm
    "Load osmAG (.osm)": "加载 osmAG (.osm)",
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
        ("将 osmAG 文件（semantic 或 fix-id 变体；由本插件、JOSM 或其他 osmAG 工具写出）打开为区域多边形图层"
         "和通道线图层，每个标签作为一个字段（另有 osm_id，以及将每个通道的区域解析为其 way 标识的 from_id "
         "/ to_id，两个楼梯或电梯区域之间的通道还有 vertical = yes）。区域按 osmAG:areatype 着色，通道绘制为"
         "粗红线，垂直通道为粗蓝线（styles/osmag_*.qml），两者都以名称标注；GeoPackage 输出保留样式。悬空引"
         "用（缺失的节点、引用未知区域的通道）和未闭合的区域 way 会被报告并跳过。不含任何 osmAG 区域的文件将"
         "被拒绝。\n"
         "INPUT：osmAG 文件（.osm，OpenStreetMap XML，坐标为 WGS84 度）。\n"
         "TARGET_CRS：输出图层的坐标系（默认 WGS84，EPSG:4326）；如需测量或编辑区域，请选择以米为单位的投影"
         "坐标系。\n"
         "OUTPUT_AREAS / OUTPUT_PASSAGES：两个图层（临时图层、GeoPackage……）。\n"
         "输出：加载的区域和通道数量（AREA_COUNT、PASSAGE_COUNT），跳过的未闭合区域 way（UNCLOSED）和悬空引"
         "用（DANGLING），根节点位置（ROOT_LON、ROOT_LAT，度）以及检测到的 VARIANT。"),
    "Output CRS": "输出坐标系",
    "osmAG areas": "osmAG 区域",
    "osmAG passages": "osmAG 通道",
    "Areas loaded": "已加载的区域",
    "Passages loaded": "已加载的通道",
    "Unclosed area ways (skipped)": "未闭合的区域 way（已跳过）",
    "Dangling references (skipped)": "悬空引用（已跳过）",
    "Root node longitude": "根节点经度",
    "Root node latitude": "根节点纬度",
    "Variant detected": "检测到的变体",
    # --- MergeFloorsAlgorithm
    "Merge osmAG floors into a building": "将 osmAG 楼层合并为建筑",
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
        ("将各楼层合并为一个 osmAG 建筑。INPUT：osmAG 楼层文件（semantic 或 fix-id），和/或按 'level' 字段拆"
         "分的 AREAS/PASSAGES 图层（如来自“加载 osmAG”）。\n"
         "每个楼层的楼层号：LEVELS（以逗号分隔，按输入顺序），否则为楼层的 level 标签，否则取自其文件名（"
         "*-F3*、*_L-1*、*B1*、*3F*、*三层*）。HEIGHTS：每层的米数（一个值用于全部楼层，或每层一个；默认：楼"
         "层的 height 标签，否则为 3.2）。\n"
         "配准：在不同坐标系中绘制的楼层通过楼梯和电梯（类型为 stairs/elevator 或按此命名的区域）相互对齐："
         "先按名称匹配，否则按类型、大小和位置，以一致性投票决定（一个错误匹配不会移动楼层）；两个锚点一致时"
         "也求解旋转。日志给出每个锚点的残差和 RMS。没有锚点的楼层按其轮廓配准，并给出警告。\n"
         "拼接：相邻楼层重叠的楼梯/电梯获得一个垂直通道（位于两个竖井内的两节点 way，标注上层楼层和高度）。"
         "一个建筑结构区域是每层一个结构区域的父区域，后者又是该层各区域的父区域；标识和名称在整栋建筑内唯一"
         "。引用不存在区域的通道会连同其标识一起报告并被舍弃（STRICT：改为停止）。REGISTER（默认开启）：按上"
         "述方法将各楼层对齐；关闭：每个楼层保持原位。BUILDING：建筑名称（根结构区域）。VARIANT：写出的 "
         "osmAG 变体：与输入相同、semantic（通道按名称引用区域）或 fix-id（通道给出 way 标识）。\n"
         "输出：OUTPUT，一个 osmAG 文件（以原子方式写出）；可选的 OUTPUT_AREAS 和 OUTPUT_PASSAGES 图层，带 "
         "'level' 字段；FLOOR_COUNT、VERTICAL_PASSAGES、AREA_COUNT 和 PASSAGE_COUNT（写出的数量）、RMS（配准"
         "残差，单位米）、DROPPED_PASSAGES（舍弃的通道）和 LEVELS_OUT（各楼层，按顺序）。"),
    "osmAG floor files": "osmAG 楼层文件",
    "Areas layer (several floors, 'level' field)": "区域图层（多个楼层，'level' 字段）",
    "Passages layer": "通道图层",
    "Levels, one per floor file (empty: level tags, else file names)":
        "楼层，每个楼层文件一个（留空：level 标签，否则取自文件名）",
    "Height per level in metres (one value, or one per floor)": "每层高度，单位米（一个值，或每层一个）",
    "Building name": "建筑名称",
    "Register the floors on their stairs/lifts (off: keep them where they are)":
        "通过楼梯/电梯对齐各楼层（关闭：保持原位）",
    "Stop on passages whose areas are missing (off: report and leave them out)":
        "遇到引用缺失区域的通道时停止（关闭：报告并舍弃）",
    "Building osmAG file": "建筑 osmAG 文件",
    "Building areas": "建筑区域",
    "Building passages": "建筑通道",
    "Floors": "楼层",
    "Vertical passages": "垂直通道",
    "Registration residual RMS (m)": "配准残差 RMS（米）",
    "Passages left out": "舍弃的通道",
    "Levels": "楼层",
    "INPUT: give at least one osmAG floor file (or an AREAS layer)":
        "INPUT：请至少给出一个 osmAG 楼层文件（或一个 AREAS 图层）",
    "HEIGHTS must be numbers (metres), e.g. 3.2 or 4.5,3.2,3.2":
        "HEIGHTS 必须是数字（米），如 3.2 或 4.5,3.2,3.2",
    "floor file '{}' does not exist": "楼层文件 '{}' 不存在",
    "AREAS has no CRS (CAD frame): georeference it first (cad2osmag:georeference)":
        "AREAS 没有坐标系（CAD 坐标系）：请先进行地理配准（cad2osmag:georeference）",
    "LEVELS gives {} levels for {} floors; give one per floor, in the order of the inputs":
        "LEVELS 给出了 {} 个楼层，而楼层文件有 {} 个；请按输入顺序每层给出一个",
    "level {}: shift ({:.3f}, {:.3f}) m, rotation {:.3f}°, {}":
        "楼层 {}：平移 ({:.3f}, {:.3f}) m，旋转 {:.3f}°，{}",
    # --- RasterizeAlgorithm
    "Rasterize structure": "栅格化建筑结构",
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
        ("将结构线（“从 DXF/DWG 提取建筑结构”的 WALLS 输出，或任何以米为单位的线/面图层）转换为单波段占用 "
         "GeoTIFF：0 = 空闲，255 = 占用（与 ROS map_server 图像相反，后者黑色为占用）。细线按 0.15 m 宽绘制"
         "，宽多段线按其宽度绘制，填充轮廓（实体填充）按填充绘制。\n"
         "范围为所有顶点的 PERCENTILES（下限、上限），扩展到伸入其中的实体，再加上 PADDING（建筑尺寸的比例）"
         "，使远处零散的实体不会把栅格撑大。原点对齐到 RESOLUTION 的整数倍，地理变换将像素精确映射回图纸坐标"
         "系。\n"
         "修复：用 KERNEL x KERNEL 的正方形做闭运算，弥合约 0.2 m 以内的缝隙，然后做开运算去除孤立斑点（开运"
         "算后不复存在且较小的连通块）。STROKE：绘制细线所用的宽度，单位米（0.15 m）。\n"
         "多楼层组：将所有楼层的结构图层作为 FLOOR_LAYERS 给出（和/或在第一层坐标系中给出 COMMON_EXTENT）；"
         "以相同参数栅格化的每个楼层都得到逐像素相同的栅格。原点不同的楼层（范围不重叠）通过互相关配准（"
         "ALIGN_FLOORS）；每个栅格的地理变换仍将其像素映射到各自的图纸坐标系，因此原点相差楼层偏移量，但像素"
         "对齐。\n"
         "超过 MAX_MPX 百万像素的栅格会以错误停止，错误信息会建议一个分辨率。\n"
         "STAIRS_AS_OBSTACLES：将楼梯和电梯符号绘制为墙（默认关闭：楼梯和电梯保持为空闲空间，从而成为区域）"
         "。DOORS（可选）：门洞线（门垛到门垛，“提取建筑结构”的 DOORS 输出），即使绘有门图层也保持开放。\n"
         "输出：OCCUPANCY，GeoTIFF（位于图纸坐标系，单位米）；WIDTH 和 HEIGHT，单位像素；OCCUPIED_SHARE，占"
         "用像素的比例（0-1）。"),
    "Resolution (m/pixel)": "分辨率（米/像素）",
    "Padding (fraction of the building size)": "外扩边距（建筑尺寸的比例）",
    "Vertex percentiles for the extent (low, high)": "用于确定范围的顶点百分位数（下限, 上限）",
    "Repair kernel (pixels, 0 = no repair)": "修复核（像素，0 = 不修复）",
    "Width of hairlines (m)": "细线宽度（米）",
    "Pixel budget (megapixels)": "像素预算（百万像素）",
    "Common extent for multi-floor sets (optional)": "多楼层组的公共范围（可选）",
    "Structure layers of all floors: rasterize on their common extent (optional)":
        "所有楼层的结构图层：在其公共范围上栅格化（可选）",
    "Register the floors (translation) before building the common grid": "在建立公共栅格之前配准各楼层（平移）",
    "automatic (only when the floors do not overlap)": "自动（仅当各楼层不重叠时）",
    "yes": "是",
    "no": "否",
    "Draw stair and lift symbols as obstacles": "将楼梯和电梯符号绘制为障碍物",
    "Doorways (jamb-to-jamb lines) kept open (optional)": "保持开放的门洞（门垛到门垛的线，可选）",
    "Occupancy raster": "占用栅格",
    "Raster width (pixels)": "栅格宽度（像素）",
    "Raster height (pixels)": "栅格高度（像素）",
    "Share of occupied pixels": "占用像素比例",
    "The structure layer (WALLS) could not be loaded.": "无法加载结构图层（WALLS）。",
    "PERCENTILES must be two numbers such as '0.5, 99.5', got '{}'":
        "PERCENTILES 必须是两个数字，如 '0.5, 99.5'，实际为 '{}'",
    ("The structure layer is in a geographic CRS ({}); rasterize needs metres: use the WALLS output of "
     "'Extract structure from DXF/DWG' or reproject to a projected CRS first."):
        ("结构图层采用地理坐标系（{}）；栅格化需要以米为单位：请使用“从 DXF/DWG 提取建筑结构”的 WALLS 输出，"
         "或先重投影到投影坐标系。"),
    "This floor is offset by ({:.3f}, {:.3f}) m from the first floor layer":
        "该楼层相对于第一层图层偏移 ({:.3f}, {:.3f}) m",
    "Cannot write the raster '{}': {}": "无法写出栅格 '{}'：{}",
    "{} x {} px at {} m/px, origin ({:.3f}, {:.3f}), {:.1%} occupied":
        "{} x {} px，{} m/px，原点 ({:.3f}, {:.3f})，占用 {:.1%}",
    # --- Cad2OsmagAlgorithm
    "{}: features with ids {} have empty or missing geometries; remove them or fix the layer":
        "{}：标识为 {} 的要素几何为空或缺失；请删除这些要素或修复图层",
    "PASSAGES: passage {} has no valid {} (value {!r}); it must name the id of an area":
        "PASSAGES：通道 {} 没有有效的 {}（值 {!r}）；它必须给出某个区域的标识",
    "PASSAGES: passage {} has no line geometry": "PASSAGES：通道 {} 没有线几何",
    "cannot write passage {} to the output layer": "无法将通道 {} 写入输出图层",
    # --- RefineAlgorithm
    "Refine areas (simplify, remove spikes, merge small areas)": "优化区域（简化、去除尖刺、合并小区域）",
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
        ("使分割得到的区域轻量、整洁，同时相邻区域沿共享边界保持相同的顶点。两个交汇点之间的每条边界只用 "
         "Douglas-Peucker 简化一次（容差 EPSILON_PX x RESOLUTION，即报告的物理误差上限），反复去除尖刺（角度"
         "小于 SPIKE_ANGLE、突出小于 SPIKE_LENGTH），通道端点固定不动，因此每个通道仍是一条线段，其两端都是"
         "所连接两个区域的顶点。小于 MIN_AREA 的区域并入与其共享边界最长的相邻区域（楼梯和电梯保留）；孤立的"
         "小区域被舍弃。请以米为单位工作：在 CAD 坐标系中运行（地理配准之前），或在投影坐标系中运行。\n"
         "AREAS 和 PASSAGES：“分割”的输出（PASSAGES 可选）。RESOLUTION：描绘区域时所用的栅格分辨率，单位米/"
         "像素。EPSILON_PX 单位为像素，SPIKE_ANGLE 单位为度，SPIKE_LENGTH 单位为米，MIN_AREA 单位为 m²。\n"
         "输出：OUTPUT_AREAS 和 OUTPUT_PASSAGES，优化后的图层；VERTICES_BEFORE、VERTICES_AFTER 和 "
         "VERTEX_REDUCTION（%）；MAX_DEVIATION，与未简化区域的最大距离（米）；EPSILON_M，以米为单位的容差；"
         "写出的 AREA_COUNT 和 PASSAGE_COUNT；MERGED 和 DROPPED，合并和舍弃的小区域；COMPONENTS，区域图的连"
         "通部分数，以及 LARGEST_COMPONENT_SHARE，最大连通部分所占的面积比例。"),
    "Raster resolution r the areas were traced at (m/px)": "描绘区域时的栅格分辨率 r（米/像素）",
    "Douglas-Peucker tolerance ε (pixels)": "Douglas-Peucker 容差 ε（像素）",
    "Spike angle below (degrees)": "尖刺角度小于（度）",
    "Spike protrusion below (m)": "尖刺突出小于（米）",
    "Refined areas": "优化后的区域",
    "Refined passages": "优化后的通道",
    "Vertices before": "简化前顶点数",
    "Vertices after": "简化后顶点数",
    "Vertex reduction (%)": "顶点减少（%）",
    "Maximum deviation from the unsimplified areas (m)": "与未简化区域的最大偏差（米）",
    "Tolerance ε·r (m)": "容差 ε·r（米）",
    "Small areas merged": "合并的小区域",
    "Isolated small areas dropped": "舍弃的孤立小区域",
    "Connected components of the area graph": "区域图的连通分量",
    "Share of the area in the largest component": "最大连通分量的面积比例",
    ("AREAS is in a geographic CRS ({}); refinement works in metres: run it on the CAD frame (before "
     "georeferencing) or reproject to a projected CRS first"):
        ("AREAS 采用地理坐标系（{}）；优化以米为单位进行：请在 CAD 坐标系中运行（地理配准之前），或先重投影"
         "到投影坐标系"),
    # --- RouteAlgorithm
    "Plan a route on an osmAG map": "在 osmAG 地图上规划路线",
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
        ("在 osmAG 地图上为半径 ROBOT_RADIUS（米）的圆形机器人规划最短路线：INPUT，osmAG 文件（本插件或任何"
         "其他工具写出，semantic 或 fix-id），或 AREAS/PASSAGES 图层（如来自 loadosmag 或 refine）。START 和"
         " END 是在地图画布上拾取的点（任意坐标系）及其楼层（START_LEVEL/END_LEVEL，楼层重叠时需要），或区域"
         "名称（START_NAME/END_NAME）。位于机器人可通行空间之外 1 m 以内的点会被移入其中；更远则报错。窄于两"
         "倍半径的通道被关闭；在每个区域内，路线是绕开墙体的最短无碰撞路径。垂直通道（楼梯、电梯）每层的代价"
         "为 VERTICAL_COST 米；AVOID 排除楼梯（只用电梯）或电梯，并使机器人与它们保持其半径的距离：它们的门口对机器人而言是墙"
         "（START 或 END 位于此类区域内时仍经其门离开）。结果是一条三维线（z = 楼层 x 高度），附带长"
         "度、代价、每个顶点的楼层以及经过的区域和通道。没有路线时，消息会指出起点和终点所在的地图互不连通的"
         "部分，以及对机器人来说过窄的通道。\n"
         "输出：OUTPUT，路线；LENGTH（米）和 COST（长度 + 垂直代价，米）；LEVEL_CHANGES；START_SNAP 和 "
         "END_SNAP，起点和终点被移动的距离（米）；QUERY_MS，搜索时间，单位毫秒；AREAS_CROSSED、"
         "PASSAGES_CROSSED 和 LEVELS（每个顶点的楼层）。"),
    "osmAG file (or give AREAS and PASSAGES)": "osmAG 文件（或给出 AREAS 和 PASSAGES）",
    "Areas layer (instead of the file)": "区域图层（代替文件）",
    "Start point": "起点",
    "Start level": "起点楼层",
    "Start area name (instead of a point)": "起点区域名称（代替点）",
    "End point": "终点",
    "End level": "终点楼层",
    "End area name (instead of a point)": "终点区域名称（代替点）",
    "Robot radius (m)": "机器人半径（米）",
    "Avoid": "避开",
    "Cost of one level of stairs or lift (m)": "楼梯或电梯每层的代价（米）",
    "Route": "路线",
    "Route length (m)": "路线长度（米）",
    "Route cost (length + vertical cost)": "路线代价（长度 + 垂直代价）",
    "Level changes": "楼层变换次数",
    "Start moved by (m)": "起点移动距离（米）",
    "End moved by (m)": "终点移动距离（米）",
    "Search time (ms)": "搜索时间（毫秒）",
    "Areas crossed": "经过的区域",
    "Passages crossed": "经过的通道",
    "Level of every vertex": "每个顶点的楼层",
    "give an osmAG file (INPUT) or an AREAS layer (with PASSAGES)":
        "请给出 osmAG 文件（INPUT）或 AREAS 图层（及 PASSAGES）",
    "PASSAGES is in {} but AREAS is in {}; reproject it first":
        "PASSAGES 位于 {}，但 AREAS 位于 {}；请先重投影",
    "{}: give a point or an area name ({})": "{}：请给出一个点或一个区域名称（{}）",
    "route: {:.2f} m ({} level changes) through {}": "路线：{:.2f} m（{} 次楼层变换），经过 {}",
    "nothing": "无",
    "stairs (wheelchairs, wheeled robots: lifts only)": "楼梯（轮椅、轮式机器人：只用电梯）",
    "lifts (evacuation: stairs only)": "电梯（疏散：只用楼梯）",
    # --- SampleBuildingAlgorithm
    "Generate sample building (DXF)": "生成示例建筑 (DXF)",
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
        ("将一栋逼真的多层办公楼写为 DXF 文件（毫米、NCS 图层、有实际厚度的墙、以块表示的门、玻璃、一个楼梯"
         "核心筒和一部电梯、以 TEXT、MTEXT 和 ATTRIB 表示的房间名称、0 图层上的嵌套块、家具和尺寸标注），并"
         "为每层写出一个真值 GeoJSON（房间、门、楼梯/电梯锚点，单位米）。相同的种子总是得到逐字节相同的文件"
         "。可用它试用或评测处理流程。\n"
         "FLOORS：楼层数（1-20），每层一个 DXF 和一个真值文件；所有楼层共用楼梯核心筒和电梯，因此上下对齐。"
         "\n"
         "SEED：任意整数；改变房间布局（0 为 README 中展示的布局）。\n"
         "PREFIX：文件名的开头：PREFIX-F1.dxf、PREFIX-F1.gt.geojson……\n"
         "OUTPUT_FOLDER：写出文件的位置（不存在时创建）。\n"
         "输出：FIRST_FLOOR_DXF（第一层的 DXF）、DXF_FILES（所有 DXF，以 ';' 分隔）、GROUND_TRUTH_FILES（真"
         "值 GeoJSON 文件，以 ';' 分隔）和 FLOOR_COUNT（写出的楼层数）。"),
    "Number of floors": "楼层数",
    "Random seed (layout variations)": "随机种子（布局变化）",
    "File name prefix": "文件名前缀",
    "DXF of the first floor": "第一层的 DXF",
    "All DXF files (semicolon separated)": "所有 DXF 文件（以分号分隔）",
    "Ground-truth GeoJSON files (semicolon separated)": "真值 GeoJSON 文件（以分号分隔）",
    "Number of floors written": "写出的楼层数",
    "Wrote {}": "已写出 {}",
    # --- SegmentAlgorithm
    "Segment occupancy grid into an Area Graph": "将占用栅格分割为区域图",
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
        ("区域图（Area Graph）分割（Hou 等，2019），采用 CAD-to-osmAG 方法的动态 alpha。INPUT 为“栅格化”的输"
         "出，或任何占用栅格：GeoTIFF、带 RESOLUTION（米/像素）的 PNG/PGM 图像，或 ROS map.yaml（使用其 "
         "resolution、origin、negate 和阈值；未知栅格单元永不视为空闲）。只分割建筑外围以内的空闲空间：窄于 "
         "ENVELOPE_GAP 的立面开口会被弥合，室外空间永远不是区域；日志报告室内面积。alpha = "
         "ceil((min(DOOR_WIDTH, CORRIDOR_WIDTH) + DELTA)^2 / (4 r^2)) px^2 为探测圆盘：它穿过开口扫过的空间"
         "属于同一房间；明显窄于其后空间的门宽收窄处将房间分开（这也能找到对圆盘来说过窄的房间）；在没有理由"
         "拆分的地方合并走廊单元；空闲空间被细化为骨架（广义 Voronoi 图），删除短于 PRUNE 的末端分支，每条骨"
         "架边（在收窄处断开）起初为一个区域。输出：AREAS（沿像素边的精确多边形：id、type room/corridor、面"
         "积、周长、最大净空），PASSAGES（横跨两个区域之间每个开口的线段，两端在墙上：from、to、width），"
         "LABELS（输入栅格上的区域标识，区域外为 0），以及按需输出的 SKELETON（每条骨架边一条线：id、长度、"
         "最小和最大净空）。对室外开放的空间在有证据时仍视为室内：平面图的建筑轮廓（开口最大为 3 x "
         "ENVELOPE_GAP，在立面墙端点之间的弦处封闭，该处经门洞通向室内）以及可选的 TEXTS（房间名称，来自“提"
         "取建筑结构”：包含房间名称的空间永远不在室外）。FOOTPRINT：默认对“栅格化”生成的栅格（CAD 平面图）使"
         "用建筑轮廓，对图像和 ROS 地图（机器人地图，房间旁的空闲空间是扫描结束的地方）不使用。可选的 DOORS"
         "（门垛到门垛的线）保持开放，并在分割遗漏的地方成为通道。每个区域都有 'component' 字段：其在区域图"
         "中的连通分量（0 = 最大的）；日志列出其他分量（没有通道可达的房间）。STRUCTURE（可选）：图纸的结构"
         "线（“提取建筑结构”的 WALLS）；其中的楼梯和电梯符号将所在区域的类型设为 stairs/elevator。TOPOLOGY_CELL（0.088 m）：骨架、区域和合并在约此大小的单元上进行（不超过它的栅格单元最大整数倍；只有单元内所有像素都空闲时单元才空闲，因此墙体永不打开），轮廓和通道在栅格自身的像素上描绘；0 = 全部在栅格像素上进行（在 0.044 m 的 CAD 栅格上约慢一倍）。\n"
         "统计值：AREA_COUNT、ROOM_COUNT、CORRIDOR_COUNT、PASSAGE_COUNT；INTERIOR_AREA_M2，建筑内的空闲面积"
         "（m²）；COMPONENTS 和 LARGEST_COMPONENT_SHARE（最大连通分量所占的面积比例）；ALPHA，探测圆盘，单位"
         " px²；SECONDS，分割用时。"),
    "Occupancy grid (GeoTIFF, PNG/PGM, or ROS map.yaml)": "占用栅格（GeoTIFF、PNG/PGM 或 ROS map.yaml）",
    "Resolution of a plain image (m/px; 0 = from the raster)": "普通图像的分辨率（米/像素；0 = 取自栅格）",
    "Narrowest corridor (m)": "最窄走廊（米）",
    "Delta δ added to the width (m)": "宽度附加量 δ（米）",
    "Prune Voronoi branches shorter than (m)": "剪除短于此值的 Voronoi 分支（米）",
    "Bridge facade openings up to (m)": "弥合不超过此宽度的立面开口（米）",
    "Cell size of the skeleton and merges (m; 0 = the raster's cells)": "骨架与合并的单元大小（米；0 = 栅格自身的单元）",
    "Structure lines of the drawing (WALLS of 'Extract structure'), to recognise stairs and lifts":
        "图纸的结构线（“提取建筑结构”的 WALLS），用于识别楼梯和电梯",
    "Use the plan's footprint as evidence of inside space": "将平面图的建筑轮廓作为室内空间的证据",
    "automatic (CAD rasters from 'Rasterize': yes; images and ROS maps: no)":
        "自动（来自“栅格化”的 CAD 栅格：是；图像和 ROS 地图：否）",
    "Room names (TEXTS of 'Extract structure'): evidence of inside space":
        "房间名称（“提取建筑结构”的 TEXTS）：室内空间的证据",
    "Doorways (jamb-to-jamb lines) kept open and made passages": "保持开放并作为通道的门洞（门垛到门垛的线）",
    "Area id raster": "区域标识栅格",
    "Skeleton (Voronoi graph edges)": "骨架（Voronoi 图的边）",
    "Rooms": "房间",
    "Corridors": "走廊",
    "Free area inside the building (m²)": "建筑内的空闲面积（m²）",
    "alpha (px²)": "alpha（px²）",
    "Segmentation time (s)": "分割用时（秒）",
    "INPUT: '{}' does not exist": "INPUT：'{}' 不存在",
    "INPUT: the raster cannot be opened": "INPUT：无法打开栅格",
    "INPUT: '{}' is not a raster file on disk": "INPUT：'{}' 不是磁盘上的栅格文件",
    "RESOLUTION ignored: the GeoTIFF carries {} m/px": "已忽略 RESOLUTION：GeoTIFF 自带 {} m/px",
    "Grid {} x {} px at {} m/px": "栅格 {} x {} px，{} m/px",
    "{} room-name points used as evidence of inside space": "{} 个房间名称点被用作室内空间的证据",
    "Footprint evidence: {}": "建筑轮廓证据：{}",
    "{} stair/lift areas recognised from their symbols": "根据符号识别出 {} 个楼梯/电梯区域",
    "Interior free area: {:.1f} m² (of {:.1f} m² free in the raster)":
        "室内空闲面积：{:.1f} m²（栅格中空闲面积共 {:.1f} m²）",
    "Timing (s): ": "耗时（秒）：",
    "Skeleton: {} nodes, {} edges, {} branches shorter than PRUNE pruned":
        "骨架：{} 个节点，{} 条边，剪除了 {} 条短于 PRUNE 的分支",
    "cannot write area {}": "无法写出区域 {}",
    "cannot write passage {}": "无法写出通道 {}",
    "cannot write skeleton edge {}": "无法写出骨架边 {}",
    "{} areas ({} rooms, {} corridors), {} passages": "{} 个区域（{} 个房间，{} 条走廊），{} 个通道",
    # --- Cad2OsmagProvider
    "CAD to osmAG": "CAD 转 osmAG",
    # --- ConvertWizard
    "1. Floor plans": "1. 平面图",
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure."):
        ("选择建筑的 DXF/DWG 文件，每层一个（最底层在前）。表格显示所选文件的图层，以及图层规则将哪些图层保"
         "留为结构。"),
    "Add files…": "添加文件…",
    "Remove": "移除",
    "Up": "上移",
    "Down": "下移",
    "Layer": "图层",
    "Kind": "类型",
    "Kept": "保留",
    "Entities": "实体数",
    "Floor plans": "平面图",
    "CAD drawings (*.dxf *.dwg *.DXF *.DWG)": "CAD 图纸 (*.dxf *.dwg *.DXF *.DWG)",
    "Cannot read the layers of {}.": "无法读取 {} 的图层。",
    "{}: {} layers, kept: {}": "{}：{} 个图层，保留：{}",
    "2. Segmentation settings (metres)": "2. 分割设置（米）",
    "The defaults suit most buildings. Smaller pixels follow thin walls better but take longer.":
        "默认值适合大多数建筑。像素越小越能贴合薄墙，但耗时越长。",
    "Raster resolution": "栅格分辨率",
    "Widest door": "最宽门宽",
    "Corridor width": "走廊宽度",
    "Merge areas smaller than": "合并小于此面积的区域",
    "Level of the first floor": "第一个文件的楼层",
    "Floor height": "层高",
    "Preview the areas of the first floor": "预览第一层的区域",
    "Previewing the segmentation": "正在预览分割结果",
    "Preview failed: {}": "预览失败：{}",
    "canceled": "已取消",
    "Computing…": "正在计算…",
    "{} areas, {} passages": "{} 个区域，{} 个通道",
    "3. Place the plan on the map": "3. 在地图上放置平面图",
    ("Add a basemap, then drag the plan to its place, turn it with the round handle, or click control "
     "points (drawing point, then map point). Every floor uses this placement."):
        ("添加底图，然后将平面图拖到其位置，用圆形手柄旋转，或点击控制点（先图纸点，再地图点）。所有楼层都使"
         "用此放置结果。"),
    "4. Convert and export": "4. 转换并导出",
    "One osmAG file per floor is written to the output folder; the floors are added to the map, styled.":
        "每层一个 osmAG 文件写入输出文件夹；各楼层以带样式的形式添加到地图。",
    "…": "…",
    "Also write the merged building (building.osm)": "同时写出合并后的建筑 (building.osm)",
    "Add the styled floors to the map": "将带样式的楼层添加到地图",
    "Convert": "转换",
    "Cancel": "取消",
    "Choose an output folder first.": "请先选择输出文件夹。",
    "Converting floor plans to osmAG": "正在将平面图转换为 osmAG",
    "Converting {} floor(s)…": "正在转换 {} 个楼层…",
    "Done: {} floor(s) written to {}": "完成：{} 个楼层已写入 {}",
    "Stopped: {}": "已停止：{}",
    "5. Names and types": "5. 名称和类型",
    ("Correct the name and the type of any area (room, corridor, stairs, elevator, structure), then save: "
     "the osmAG files are written again."):
        ("更正任意区域的名称和类型（room、corridor、stairs、elevator、structure），然后保存：osmAG 文件将重"
         "新写出。"),
    "Area": "区域",
    "Name": "名称",
    "Type": "类型",
    "Save and export again": "保存并重新导出",
    "{} areas": "{} 个区域",
    "Exporting osmAG again": "正在重新导出 osmAG",
    "Saving {} changed areas…": "正在保存 {} 个已更改的区域…",
    "{} areas changed; osmAG files written again.": "{} 个区域已更改；osmAG 文件已重新写出。",
    "Export failed: {}": "导出失败：{}",
    "Convert a floor plan to osmAG": "将平面图转换为 osmAG",
    # --- Placement
    "the plan has no structure lines to show": "平面图没有可显示的结构线",
    "Plan placement: {}": "平面图放置：{}",
    "the CAD to osmAG Processing provider is not loaded": "未加载 CAD 转 osmAG 处理提供程序",
    "cannot read the structure of {}": "无法读取 {} 的结构",
    # --- PlacementDock
    "Load floor plan…": "加载平面图…",
    "OSM basemap": "OSM 底图",
    "Satellite basemap": "卫星底图",
    "No plan loaded.": "尚未加载平面图。",
    "Move / rotate / scale": "移动 / 旋转 / 缩放",
    ("Drag the plan to move it, the round handle to rotate it (Shift: whole degrees), the square handle to "
     "scale it."):
        "拖动平面图以移动，拖动圆形手柄以旋转（Shift：整度），拖动方形手柄以缩放。",
    "Control points": "控制点",
    ("Click a point of the drawing, then the same point on the basemap; repeat (right click cancels a half "
     "pair)."):
        "先点击图纸上的一个点，再点击底图上的同一点；重复此操作（右键取消未完成的一对）。",
    "Drawing origin longitude": "图纸原点经度",
    "Drawing origin latitude": "图纸原点纬度",
    "Rotation (clockwise from north)": "旋转角（自正北顺时针）",
    "Scale (ground m per drawing m)": "比例（地面米/图纸米）",
    "Control points: keep the scale (solve position and rotation only)":
        "控制点：保持比例不变（只求解位置和旋转）",
    "Drawing x (m)": "图纸 x（米）",
    "Drawing y (m)": "图纸 y（米）",
    "Longitude": "经度",
    "Latitude": "纬度",
    "Residual (m)": "残差（米）",
    "RMS: – (add at least 2 control points)": "RMS：–（请至少添加 2 个控制点）",
    "Remove point": "删除点",
    "The placement is saved with the project and used for every floor of the building.":
        "放置结果随项目保存，并用于建筑的每一层。",
    "Floor plan": "平面图",
    "Cannot load {}: {}": "无法加载 {}：{}",
    "{}: {} lines, {:.1f} × {:.1f} m": "{}：{} 条线，{:.1f} × {:.1f} m",
    "Cannot fit: {}": "无法拟合：{}",
    "RMS: {:.3f} m ({} points)": "RMS：{:.3f} 米（{} 个点）",
    "Place the plan on the map": "在地图上放置平面图",
    # --- Cad2OsmagModel
    ("The whole conversion of one floor as a graphical model of the individual algorithms: extract the "
     "structure of the DXF, rasterize it, segment the free space into an Area Graph (stairs and lifts typed "
     "from the drawing), refine the areas, georeference them (the drawing origin at ANCHOR, ROTATION "
     "clockwise from north, SCALE) and export osmAG. Open it in the graphical modeler to add or change "
     "steps."):
        ("以各个算法组成的图形模型完成一个楼层的完整转换：提取 DXF 的建筑结构，栅格化，将空闲空间分割为区域"
         "图（Area Graph，楼梯和电梯的类型取自图纸），优化区域，进行地理配准（图纸原点位于 ANCHOR，ROTATION "
         "为自正北顺时针的角度，SCALE）并导出 osmAG。可在图形建模器中打开以添加或修改步骤。"),
    ("Where the drawing origin (0, 0) lies on the map: pick it on a basemap, or use the placement of Vector "
     "▸ CAD to osmAG ▸ Place a floor plan on the map."):
        ("图纸原点 (0, 0) 在地图上的位置：在底图上拾取，或使用 矢量 ▸ CAD 转 osmAG ▸ 在地图上放置平面图 的放"
         "置结果。"),
    "Corridor width in metres (8 m, the segment default).": "走廊宽度，单位米（8 m，“分割”的默认值）。",
    "Widest door in metres (2.8 m, the segment default).": "最宽的门，单位米（2.8 m，“分割”的默认值）。",
    "The floor plan (DXF).": "平面图（DXF）。",
    "Level of the floor (osmAG level tag).": "楼层（osmAG 的 level 标签）。",
    "Areas smaller than this (m²) merge into a neighbour (stairs and lifts are kept).":
        "小于此面积（m²）的区域并入相邻区域（楼梯和电梯保留）。",
    "The osmAG file written (.osm).": "写出的 osmAG 文件（.osm）。",
    "Raster resolution in metres per pixel (0.044 m by default).": "栅格分辨率，单位米/像素（默认 0.044 m）。",
    "Direction of the drawing's +y axis, in degrees clockwise from north.":
        "图纸 +y 轴的方向，自正北顺时针的度数。",
    "Ground metres per drawing metre (1 for a correct drawing).":
        "每图纸米对应的地面米数（比例正确的图纸为 1）。",
    "DXF floor plan": "DXF 平面图",
    "osmAG areas (WGS84)": "osmAG 区域（WGS84）",
    "osmAG passages (WGS84)": "osmAG 通道（WGS84）",
    # --- not in the sources of this branch (kept for strings other branches add)
    "Convert DXF floor plan to osmAG": "将 DXF 平面图转换为 osmAG",
    "Extract structure from DXF": "从 DXF 提取建筑结构",
    "List DXF layers": "列出 DXF 图层",
    "DXF drawing": "DXF 图纸",
    "as the inputs": "与输入相同",
    "List the plans on a DXF/DWG sheet": "列出 DXF/DWG 图幅上的平面图",
    ("Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, and "
     "lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON layer "
     "rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its index "
     "(the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and height "
     "in metres, metres of walls, and main = true for the plan converted by default (index 0 when it is a "
     "plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and legends "
     "left out) to draw the sheet under the rectangles; draw an extent over it to give PLAN_EXTENT. "
     "MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details)."):
        ("像“从 DXF/DWG 提取建筑结构”一样查找整张图幅（DXF 或 DWG）上的平面图，并列出每一组，而不是只保留一"
         "组：INPUT 为图纸，LAYER_RULES 为可选的 JSON 图层规则。OUTPUT 为每组一个矩形，以米为单位、位于图纸"
         "自身坐标系中，字段包括序号（即 PLAN 的取值）、种类（plan、detail、legend、other）、标题（如 '三层"
         "平面图'）、宽度和高度（米）、墙体长度（米），默认转换的平面图 main = true（若序号 0 为平面图则为序"
         "号 0）。STRUCTURE（可选）为整张图幅的结构线（不含图框和图例），用于在矩形下方绘制图幅；在其上绘制"
         "范围即可给出 PLAN_EXTENT。MAIN_PLAN 为主平面图的序号（图幅上只有详图时为 -1）。"),
    "Plans on the sheet": "图幅上的平面图",
    "Structure lines of the whole sheet": "整张图幅的结构线",
    "Index of the main plan (-1: none)": "主平面图的序号（-1：无）",
    "plan": "平面图",
    "detail": "详图",
    "legend": "图例",
    "other": "其他",
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure; below, the plans found "
     "on its sheet: the main plan is pre-selected, pick another or draw an extent."):
        ("选择建筑的 DXF/DWG 文件，每层一个（最底层在前）。表格显示所选文件的图层，以及图层规则将哪些图层保"
         "留为结构；下方为在其图幅上找到的平面图：主平面图已预先选中，可选择其他平面图或绘制范围。"),
    "Plans on the sheet (the selected one is converted):": "图幅上的平面图（转换选中的一个）：",
    "Plan": "平面图",
    "Size": "尺寸",
    "Title": "标题",
    "Draw an extent on the sheet": "在图幅上绘制范围",
    ("Drag a rectangle over the sheet to convert only what lies in it (e.g. one half of a floor drawn in "
     "two parts)."):
        "在图幅上拖出一个矩形，只转换其中的内容（例如分两部分绘制的楼层的一半）。",
    "Finding the plans on {}": "正在查找 {} 上的平面图",
    "Finding the plans on the sheet…": "正在查找图幅上的平面图…",
    "plans": "平面图",
    "sheet": "图幅",
    "Cannot find the plans: {}": "无法找到平面图：{}",
    "{:.0f} × {:.0f} m": "{:.0f} × {:.0f} m",
    "{} group(s) on the sheet and no floor plan among them: pick one, or draw an extent.":
        "图幅上有 {} 组，但其中没有楼层平面图：请选择一组，或绘制范围。",
    "Converting the extent {:.1f}, {:.1f} – {:.1f}, {:.1f} m of {} group(s).":
        "正在转换范围 {:.1f}, {:.1f} – {:.1f}, {:.1f} m（共 {} 组）。",
    "Converting plan [{}] ({}{}) of {} group(s).": "正在转换平面图 [{}]（{}{}）（共 {} 组）。",
    "Snap the rotation to building edges (polygon layers on the map, within 3°)":
        "将旋转吸附到建筑边线（地图上的面图层，3° 以内）",
    ("Load building footprints (e.g. OpenStreetMap buildings) as a vector layer: while you turn the plan, "
     "its walls snap to their edges. Shift turns in whole degrees instead."):
        ("将建筑轮廓（如 OpenStreetMap 建筑）加载为矢量图层：旋转平面图时，其墙体会吸附到这些边线上。按住 "
         "Shift 则改为按整度旋转。"),
    "Rotation snapped to the building edges at {:.1f}° (modulo 90°).":
        "旋转已吸附到建筑边线，角度 {:.1f}°（模 90°）。",
    ("Finds the plans on a whole drawing sheet (DXF or DWG), as 'Extract structure from DXF/DWG' does, and "
     "lists every group instead of keeping one: INPUT is the drawing, LAYER_RULES the optional JSON layer "
     "rules. OUTPUT holds one rectangle per group, in metres in the drawing's own frame, with its index "
     "(the value of PLAN), kind (plan, detail, legend, other), title (e.g. '三层平面图'), width and height "
     "in metres, metres of walls, and main = true for the plan converted by default (index 0 when it is a "
     "plan). STRUCTURE (optional) holds the structure lines of the whole sheet (title frames and legends "
     "left out) to draw the sheet under the rectangles; draw an extent over it to give PLAN_EXTENT. "
     "MAIN_PLAN is the index of the main plan (-1 when the sheet holds only details). PLAN_COUNT is the "
     "number of groups and PLANS lists them as text."):
        ("像“从 DXF/DWG 提取建筑结构”一样查找整张图幅（DXF 或 DWG）上的平面图，并列出每一组，而不是只保留一"
         "组：INPUT 为图纸，LAYER_RULES 为可选的 JSON 图层规则。OUTPUT 为每组一个矩形，以米为单位、位于图纸"
         "自身坐标系中，字段包括序号（即 PLAN 的取值）、种类（plan、detail、legend、other）、标题（如 '三层"
         "平面图'）、宽度和高度（米）、墙体长度（米），默认转换的平面图 main = true（若序号 0 为平面图则为序"
         "号 0）。STRUCTURE（可选）为整张图幅的结构线（不含图框和图例），用于在矩形下方绘制图幅；在其上绘制"
         "范围即可给出 PLAN_EXTENT。MAIN_PLAN 为主平面图的序号（图幅上只有详图时为 -1）。PLAN_COUNT 为组数，"
         "PLANS 以文字形式列出各组。"),
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first). The table shows the "
     "layers of the selected file and which ones the layer rules keep as structure; below, the plans found "
     "on its sheet: the main plan is pre-selected, click another (in the list or on the sheet) or draw an "
     "extent."):
        ("选择建筑的 DXF/DWG 文件，每层一个（最底层在前）。表格显示所选文件的图层，以及图层规则将哪些图层保"
         "留为结构；下方为在其图幅上找到的平面图：主平面图已预先选中，可点击其他平面图（在列表中或图幅上）或"
         "绘制范围。"),
    ("Pick the DXF/DWG files of the building, one per floor (bottom floor first), "
     "and check the layers kept as structure and the plan converted on each sheet."):
        '选择建筑的 DXF/DWG 文件，每层一个（最低层在前），并检查作为结构保留的图层以及每张图幅上要转换的平面图。',
    ("Plans on the sheet: the selected one is converted. The main plan (★) is "
     "pre-selected; click another in the list or on the sheet, or draw an extent."):
        '图幅上的平面图：转换选中的一个。主平面图（★）已预选；可在列表或图幅上点击另一个，或绘制一个范围。',
}

# extractstructure help with the TEXTS layer's hidden field
T["Reads INPUT, a DXF floor plan or a DWG (AutoCAD R13-2018, read directly: no converter needed), explodes blocks (with scale, rotation, mirror and MINSERT arrays; entities on layer 0 inside a block take the INSERT's layer), skips frozen and off layers, keeps the structural layers chosen by the layer rules (walls, columns, windows/glazing, stairs, lifts, and the reference layers 0 and Defpoints) and flattens curves to 1 cm.\nLAYER_RULES: a JSON file of case-insensitive keywords (copy algorithms/default_layer_rules.json). LAYERS: explicit layer names (separated by ';') that override the rules. UNITS: the header's $INSUNITS is only a hint; by default the unit is chosen so that the building is 5-500 m across (a warning names both units). Door layers are left out unless INCLUDE_DOORS is set, so that doorways stay open; door swings and door blocks (by name, in many languages) are found on any layer and written as DOORS (jamb to jamb); furniture blocks, free-standing furniture on layer 0 and pattern hatches are left out (the log counts every class).\nWhole sheets: title frames, title blocks and legends are left out and the structure is grouped into plans (groups more than 5 m apart); the main plan (largest wall mass) is kept, the log lists every group with its index, extent, title and kind (plan / detail / legend). PLAN picks another (an index, or xmin,ymin,xmax,ymax in metres); PLAN_EXTENT is the same extent drawn on the canvas.\nOutputs, in metres in the drawing's own frame (a local engineering CRS, not georeferenced): WALLS (lines with fields layer, kind, entity, closed, filled, width; 'Rasterize structure' rebuilds the geometry from them; block, class), TEXTS (points with text, height, rotation, layer, entity, block, tag = ATTRIB tag, id, hidden = on a frozen or off layer; 'Assign room names and types from texts' reads them) and DOORS (doorway lines with source and width). Figures: PLANS (the plans found on the sheet) and PLAN_COUNT (their number), DOOR_COUNT (doorways found), CLASSES (entities counted per class), UNIT and UNIT_SCALE (the unit used and metres per drawing unit), GEOMETRY_COUNT (structure features written) and TEXT_COUNT (texts written)."] = (
    "读取 INPUT，即 DXF 平面图或 DWG（AutoCAD R13-2018，直接读取：无需转换器），分解块（含缩放、旋转、镜像和 MINSERT 阵列；块内 0 图层上的实体采用 INSERT 的图层），跳过冻结和关闭的图层，保留图层规则选出的结构图层（墙、柱、窗/玻璃、楼梯、电梯，以及参考图层 0 和 Defpoints），并以 1 cm 精度将曲线折线化。\nLAYER_RULES：不区分大小写的关键词 JSON 文件（复制 algorithms/default_layer_rules.json）。LAYERS：显式的图层名称（以 ';' 分隔），优先于规则。UNITS：文件头中的 $INSUNITS 仅作参考；默认选择使建筑尺寸为 5-500 m 的单位（警告中会给出两种单位）。除非设置 INCLUDE_DOORS，门图层将被排除，使门洞保持开放；门的开启弧线和门块（按名称，支持多种语言）会在任意图层上被识别，并写为 DOORS（门垛到门垛）；家具块、0 图层上的独立家具和图案填充会被排除（日志统计每一类）。\n整张图幅：图框、图签和图例会被排除，结构按平面图分组（相距超过 5 m 的组）；保留主平面图（墙体最多的一组），日志列出每组的序号、范围、标题和种类（平面图 / 详图 / 图例）。PLAN 选择其他平面图（序号，或以米为单位的 xmin,ymin,xmax,ymax）；PLAN_EXTENT 为在地图画布上绘制的同样范围。\n输出，以米为单位、位于图纸自身坐标系中（局部工程坐标系，未地理配准）：WALLS（线，字段 layer、kind、entity、closed、filled、width；“栅格化建筑结构”据此重建几何；block、class）、TEXTS（点，字段 text、height、rotation、layer、entity、block、tag = ATTRIB 标记、id、hidden = 位于冻结或关闭的图层；“根据文字指定房间名称和类型”读取它们）和 DOORS（门洞线，字段 source 和 width）。统计值：PLANS（图幅上找到的平面图）和 PLAN_COUNT（其数量）、DOOR_COUNT（找到的门洞）、CLASSES（按类统计的实体数）、UNIT 和 UNIT_SCALE（所用单位及每图纸单位对应的米数）、GEOMETRY_COUNT（写出的结构要素数）和 TEXT_COUNT（写出的文字数）。")

# the model's file input takes DWG too
T['DXF or DWG floor plan'] = 'DXF 或 DWG 平面图'
T['The floor plan (DXF, or DWG as delivered: the main plan of a sheet is converted).'] = '平面图（DXF，或原样交付的 DWG：转换图幅上的主平面图）。'

# assignnames: bad input named (issue 9 audit)
T["TEXTS has no 'text' field: use the TEXTS output of 'Extract structure from DXF' (or a point layer with fields text and, optionally, layer, height, rotation, entity, block, tag, id)"] = (
    "TEXTS 没有 'text' 字段：请使用“从 DXF 提取建筑结构”的 TEXTS 输出（或带有 text 字段以及可选的 layer、height、"
    "rotation、entity、block、tag、id 字段的点图层）")
T["AREAS holds no area: nothing to name; every room text is counted as outside every area"] = (
    "AREAS 不含任何区域：没有可命名的对象；每个房间文字都计为位于所有区域之外")
T["TEXTS holds no text: every area gets its generated id (level-area id)"] = (
    "TEXTS 不含任何文字：每个区域获得其生成的编号（楼层-区域编号）")
