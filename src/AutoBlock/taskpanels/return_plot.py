"""A small live plot of training and test return against episodes (QPainter; no extra dependency)."""

from PySide2 import QtCore, QtGui, QtWidgets

TRAIN_COLOUR = QtGui.QColor(40, 100, 200)
TEST_COLOUR = QtGui.QColor(230, 120, 20)


class ReturnPlot(QtWidgets.QWidget):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.setMinimumHeight(130)
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
        rect = self.rect().adjusted(42, 8, -8, -22)
        painter.fillRect(self.rect(), self.palette().base())
        painter.setPen(self.palette().text().color())
        painter.drawRect(rect)
        points = self.train + self.test
        if not points:
            painter.drawText(rect, QtCore.Qt.AlignCenter, "training and test return\nappear here")
            return
        x0 = min(p[0] for p in points)
        x1 = max(p[0] for p in points)
        y0 = min(p[1] for p in points)
        y1 = max(p[1] for p in points)
        if x1 == x0:
            x1 = x0 + 1
        if y1 == y0:
            y0, y1 = y0 - 1, y1 + 1

        def at(p):
            return QtCore.QPointF(rect.left() + (p[0] - x0) / (x1 - x0) * rect.width(),
                                  rect.bottom() - (p[1] - y0) / (y1 - y0) * rect.height())

        painter.drawText(QtCore.QRectF(0, rect.top() - 6, 40, 14), QtCore.Qt.AlignRight, "{:.3g}".format(y1))
        painter.drawText(QtCore.QRectF(0, rect.bottom() - 8, 40, 14), QtCore.Qt.AlignRight, "{:.3g}".format(y0))
        painter.drawText(QtCore.QRectF(rect.left(), rect.bottom() + 4, rect.width(), 14), QtCore.Qt.AlignLeft,
                         "episode {:g}".format(x0))
        painter.drawText(QtCore.QRectF(rect.left(), rect.bottom() + 4, rect.width(), 14), QtCore.Qt.AlignRight,
                         "{:g}".format(x1))
        for series, colour, name, row in ((self.train, TRAIN_COLOUR, "train", 0), (self.test, TEST_COLOUR, "test", 1)):
            if not series:
                continue
            painter.setPen(QtGui.QPen(colour, 2))
            if len(series) == 1:
                painter.drawEllipse(at(series[0]), 2.5, 2.5)
            else:
                painter.drawPolyline(QtGui.QPolygonF([at(p) for p in series]))
            painter.drawText(QtCore.QPointF(rect.left() + 6, rect.top() + 14 + 14 * row), name + " return")
