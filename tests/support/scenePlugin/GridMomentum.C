// A function object hooked inside the step, as a user's library would add one: the grid's
// total mass and momentum after particles-to-grid and after the grid update, written at the
// end of the step with the time the step started from.
//     system/controlDict:   functions { grid { type gridMomentum; writeInterval 10; } }
#include "functionObjects/FunctionObject.H"

namespace scenePlugin {

class GridMomentum : public gpic::FunctionObject<2> {
public:
    GridMomentum(const gpic::Dictionary& dict, const gpic::RunContext& context) : FunctionObject<2>(dict, context) {}

    std::vector<gpic::StepPoint> stepPoints() const override
    {
        return {gpic::StepPoint::afterParticlesToGrid, gpic::StepPoint::afterGridUpdate};
    }
    void at(gpic::StepPoint point, const gpic::MpmSolver<2>& solver) override
    {
        const gpic::Grid<2>& g = solver.grid();
        gpic::Vector2 P = gpic::Vector2::Zero();
        double M = 0;
        for (int n : g.active) {
            M += g.mass[n];
            P += g.mass[n] * g.velocity[n];
        }
        const bool before = point == gpic::StepPoint::afterParticlesToGrid;
        (before ? before_ : after_) = P;
        mass_ = M;
        stepStart_ = solver.time();
    }
    void write(const gpic::MpmSolver<2>&, double time) override
    {
        std::ofstream& os = file("gridMomentum.dat");
        if (os.tellp() == 0) os << "# time stepStart mass pyBefore pyAfter\n";
        os.precision(17);
        os << time << ' ' << stepStart_ << ' ' << mass_ << ' ' << before_.y() << ' ' << after_.y() << '\n';
    }

private:
    gpic::Vector2 before_ = gpic::Vector2::Zero(), after_ = gpic::Vector2::Zero();
    double mass_ = 0, stepStart_ = 0;
};

GPIC_REGISTER(gpic::FunctionObject<2>, GridMomentum, "gridMomentum")

} // namespace scenePlugin
