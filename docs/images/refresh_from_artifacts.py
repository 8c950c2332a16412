"""Copy the GUI screenshots written by the headless tests (tests/artifacts/, see tests/test_gui_*.py) to
docs/images/ under the names the README uses, as palette PNGs (at most 150 kB each).

    QT_QPA_PLATFORM=offscreen .venv/bin/python -m pytest tests/test_gui_wizard.py tests/test_gui_placement.py \
        tests/test_gui_styles.py      # the DWG one is marked slow
    .venv/bin/python docs/images/refresh_from_artifacts.py
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ARTIFACTS = os.path.join(HERE, "..", "..", "tests", "artifacts")
MAX_BYTES = 150_000

# README image <- test artifact
IMAGES = {
    "gui_placement_canvas.png": "placement_canvas.png",
    "gui_placement_panel.png": "placement_panel.png",
    "gui_styled_floor.png": "styled_floor.png",
    "gui_wizard_1_files.png": "wizard_dwg_1_plans.png",  # a DWG sheet as delivered: layers and plans
    "gui_wizard_1_sheet.png": "wizard_1_plans.png",  # a sheet with a floor plan and a detail view
    "gui_wizard_2_settings.png": "wizard_dwg_2_settings.png",
    "gui_wizard_3_placement.png": "wizard_dwg_3_placement.png",
    "gui_wizard_4_done.png": "wizard_4_done.png",
    "gui_wizard_4_canvas.png": "wizard_dwg_4_canvas.png",  # the converted DWG floor, styled, on the map
    "gui_wizard_5_names.png": "wizard_5_names.png",
}


def main():
    from PIL import Image

    missing = []
    for target, source in IMAGES.items():
        src = os.path.join(ARTIFACTS, source)
        if not os.path.isfile(src):
            missing.append(source)
            continue
        img = Image.open(src).convert("RGB")
        colours = 256
        while True:
            out = os.path.join(HERE, target)
            img.quantize(colors=colours, method=Image.Quantize.MEDIANCUT).save(out, optimize=True)
            if os.path.getsize(out) <= MAX_BYTES or colours <= 16:
                break
            colours //= 2
        print(f"{target}: {os.path.getsize(out) // 1024} kB ({colours} colours) from {source}")
    if missing:
        print("not written by the tests yet (kept as they are):", ", ".join(missing), file=sys.stderr)


if __name__ == "__main__":
    main()
