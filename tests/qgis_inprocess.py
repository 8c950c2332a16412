"""Run a Processing algorithm inside the test's QGIS (the ``provider`` fixture), without a qgis_process start.

The headless path (``tests/qgis_process.py``) costs ~2.5 CPU s of QGIS start and plugin import per call; tests
that loop over many real plans run the same Processing classes here and keep one headless call as the check
that the command line works.
"""


def log_feedback():
    """A QgsProcessingFeedback that keeps the log in ``.lines`` (warnings and errors prefixed)."""
    from qgis.core import QgsProcessingFeedback

    class Log(QgsProcessingFeedback):
        def __init__(self):
            super().__init__()
            self.lines = []

        def pushInfo(self, info):  # noqa: N802
            self.lines.append(info)
            super().pushInfo(info)

        def pushWarning(self, warning):  # noqa: N802
            self.lines.append("WARNING " + warning)

        def pushCommandInfo(self, info):  # noqa: N802  (qgis_process prints these too)
            self.lines.append(info)

        def pushConsoleInfo(self, info):  # noqa: N802
            self.lines.append(info)

        def pushDebugInfo(self, info):  # noqa: N802
            self.lines.append(info)

        def reportError(self, error, fatalError=False):  # noqa: N802, N803
            self.lines.append("ERROR " + error)

    return Log()


def run_alg_inprocess(alg_id, params, check=False):
    """Run ``alg_id`` (``cad2osmag:<name>`` or ``<name>``) with ``params``.

    Returns (results, ok, feedback); ``feedback.lines`` holds the log (warnings and errors prefixed).
    With ``check`` a failed run fails the test with that log.
    """
    from qgis.core import QgsApplication, QgsProcessingContext, QgsProject

    if ":" not in alg_id:
        alg_id = f"cad2osmag:{alg_id}"
    alg = QgsApplication.processingRegistry().createAlgorithmById(alg_id)
    assert alg is not None, f"{alg_id} is not registered"
    context = QgsProcessingContext()
    context.setProject(QgsProject.instance())
    feedback = log_feedback()
    results, ok = alg.run(params, context, feedback)
    if check:
        assert ok, f"{alg_id} failed:\n" + "\n".join(feedback.lines)
    return results, ok, feedback
