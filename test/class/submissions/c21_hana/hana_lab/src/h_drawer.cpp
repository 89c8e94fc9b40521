// Hana's controller: an H through its corners, on P, closed loop on the pose.
#include <cmath>
#include <vector>
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <std_msgs/String.h>
#include <turtlesim/Pose.h>

class HDrawer {
 public:
  HDrawer() {
    cmd_ = n_.advertise<geometry_msgs::Twist>("turtle1/cmd_vel", 10);
    pose_sub_ = n_.subscribe("turtle1/pose", 10, &HDrawer::onPose, this);
    chatter_sub_ = n_.subscribe("chatter", 10, &HDrawer::onChatter, this);
  }

  void run() {
    ros::Rate rate(30);
    while (ros::ok()) {
      ros::spinOnce();
      if (go_ && have_pose_) {
        double x = pose_.x, y = pose_.y;
        std::vector<std::pair<double, double>> corners = {
            {x, y + 2.0}, {x, y + 1.0}, {x + 1.2, y + 1.0}, {x + 1.2, y + 2.0}, {x + 1.2, y}};
        for (auto& c : corners) goTo(c.first, c.second);
        go_ = false;
      }
      rate.sleep();
    }
  }

 private:
  void onPose(const turtlesim::Pose::ConstPtr& p) { pose_ = *p; have_pose_ = true; }
  void onChatter(const std_msgs::String::ConstPtr& m) { go_ = m->data == "P"; }

  void goTo(double x, double y) {
    ros::Rate rate(30);
    while (ros::ok()) {
      ros::spinOnce();
      double dx = x - pose_.x, dy = y - pose_.y;
      if (std::hypot(dx, dy) < 0.01) break;
      double error = std::atan2(dy, dx) - pose_.theta;
      error = std::atan2(std::sin(error), std::cos(error));
      geometry_msgs::Twist cmd;
      cmd.angular.z = 4.0 * error;
      if (std::fabs(error) < 0.2) cmd.linear.x = std::min(1.0, 2.0 * std::hypot(dx, dy));
      cmd_.publish(cmd);
      rate.sleep();
    }
    cmd_.publish(geometry_msgs::Twist());
  }

  ros::NodeHandle n_;
  ros::Publisher cmd_;
  ros::Subscriber pose_sub_, chatter_sub_;
  turtlesim::Pose pose_;
  bool have_pose_ = false, go_ = false;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "h_drawer");
  HDrawer().run();
  return 0;
}
