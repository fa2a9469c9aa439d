// relief-cli compress: a map into a GPU format, saved as DDS or KTX2, with its metrics;
// relief-cli decode: a DDS or KTX2 file back to an image; relief-cli compare: the metrics
// between a reference image and a candidate (an image or a DDS/KTX2 file).
#pragma once

#include <QStringList>

namespace relief::cli {

int runCompress(const QStringList& arguments);
int runDecode(const QStringList& arguments);
int runCompare(const QStringList& arguments);

}  // namespace relief::cli
