"""A small live plot of the training return (10-episode average, as the paper's curves) and the test return
against episodes (QPainter; no extra dependency)."""

from PySide2 import QtCore, QtGui, QtWidgets

TRAIN_COLOUR = QtGui.QColor(40, 100, 200)
TEST_COLOUR = QtGui.QColor(230, 120, 20)


class ReturnPlot(QtWidgets.QWidget):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.setMinimumHeight(200)
        self.train = []  # (episode, return)
        self.test = []

    def clear(self):
        self.train, self.test = [], []
        self.update()

    def add(self, episode, train_return=None, test_return=None):
        if train_return is not None:
            self.train.append((episode, float(train_return)))
        if test_return is not None:
            self.test.append((episode, float(test_return)))
        self.update()

    def paintEvent(self, event):
        painter = QtGui.QPainter(self)
        painter.setRenderHint(QtGui.QPainter.Antialiasing)
        painter.fillRect(self.rect(), self.palette().base())
        line = painter.fontMetrics().height()
        # The plot area, with room for the y labels (left), the x labels and the legend (below).
        rect = self.rect().adjusted(46, 8, -10, -(3 * line + 10))
        painter.setPen(self.palette().text().color())
        painter.drawRect(rect)
        for k, (colour, name) in enumerate(((TRAIN_COLOUR, "training return (10-episode average)"),
                                            (TEST_COLOUR, "test return (deterministic policy)"))):
            y = rect.bottom() + line + 6 + k * line
            x = rect.left()
            painter.setPen(QtGui.QPen(colour, 2))
            painter.drawLine(QtCore.QPointF(x, y + line / 2), QtCore.QPointF(x + 14, y + line / 2))
            painter.setPen(self.palette().text().color())
            painter.drawText(QtCore.QRectF(x + 20, y, rect.width() - 20, line), QtCore.Qt.AlignLeft, name)
        points = self.train + self.test
        if not points:
            painter.drawText(rect, QtCore.Qt.AlignCenter, "the return per episode\nappears here")
            return
        x0 = min(p[0] for p in points)
        x1 = max(p[0] for p in points)
        y0 = min(p[1] for p in points)
        y1 = max(p[1] for p in points)
        if x1 == x0:
            x1 = x0 + 1
        if y1 == y0:
            y0, y1 = y0 - 1, y1 + 1
        pad = 0.06 * (y1 - y0)  # keep the curves off the frame
        y0, y1 = y0 - pad, y1 + pad

        def at(p):
            return QtCore.QPointF(rect.left() + (p[0] - x0) / (x1 - x0) * rect.width(),
                                  rect.bottom() - (p[1] - y0) / (y1 - y0) * rect.height())

        painter.drawText(QtCore.QRectF(0, rect.top() - 2, 42, line), QtCore.Qt.AlignRight, "{:.3g}".format(y1))
        painter.drawText(QtCore.QRectF(0, rect.bottom() - line + 2, 42, line), QtCore.Qt.AlignRight,
                         "{:.3g}".format(y0))
        painter.drawText(QtCore.QRectF(rect.left(), rect.bottom() + 3, rect.width(), line), QtCore.Qt.AlignLeft,
                         "episode {:g}".format(x0))
        painter.drawText(QtCore.QRectF(rect.left(), rect.bottom() + 3, rect.width(), line), QtCore.Qt.AlignRight,
                         "{:g}".format(x1))
        for series, colour in ((self.train, TRAIN_COLOUR), (self.test, TEST_COLOUR)):
            if not series:
                continue
            painter.setPen(QtGui.QPen(colour, 2))
            if len(series) == 1:
                painter.drawEllipse(at(series[0]), 2.5, 2.5)
            else:
                painter.drawPolyline(QtGui.QPolygonF([at(p) for p in series]))
            if series is self.test:
                for p in series:
                    painter.drawEllipse(at(p), 2.0, 2.0)
