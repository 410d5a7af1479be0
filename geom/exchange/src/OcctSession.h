#pragma once
// OpenCASCADE's data exchange settings for one read or write (private to geom_exchange).

#include <TDocStd_Document.hxx>

#include <mutex>
#include <string>
#include <vector>

namespace geom::exchange {

/// Holds OpenCASCADE's data exchange for one read or write: its settings are process-wide, so a
/// lock keeps one user at a time. Initialises the controllers once (their first use would reset
/// the settings), silences OpenCASCADE's console messages, and sets the unit of shapes in memory
/// and of files written to `unitCode` ("M", "MM", ...), with exact B-splines kept on read.
class OcctSession {
public:
    /// The lock a session takes; a reader takes it before it forks (so no other thread is inside
    /// OpenCASCADE then), and its child opens its session without locking again.
    static std::unique_lock<std::mutex> lock();

    enum class Locking { Lock, AlreadyHeld };
    explicit OcctSession(const std::string& unitCode, Locking locking = Locking::Lock);
    /// Closes the session's documents (their labels and shapes hold one another: left open, they leak).
    ~OcctSession();
    OcctSession(const OcctSession&) = delete;
    OcctSession& operator=(const OcctSession&) = delete;

    /// A new XCAF document whose length unit is the session's, closed with the session.
    opencascade::handle<TDocStd_Document> newDocument();

private:
    std::unique_lock<std::mutex> lock_;
    double metres_ = 1.0;
    std::vector<opencascade::handle<TDocStd_Document>> documents_;
};

}  // namespace geom::exchange
