// Kenji's controller: a K through its corners on P, closed loop on the pose.
#include <cmath>
#include <utility>
#include <vector>
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <std_msgs/String.h>
#include <turtlesim/Pose.h>

turtlesim::Pose pose;
bool have_pose = false, go = false;

void onPose(const turtlesim::Pose::ConstPtr& m) { pose = *m; have_pose = true; }
void onChatter(const std_msgs::String::ConstPtr& m) { go = m->data == "P"; }

void goTo(ros::Publisher& cmd, double x, double y) {
  ros::Rate rate(30);
  while (ros::ok()) {
    ros::spinOnce();
    double dx = x - pose.x, dy = y - pose.y;
    if (std::hypot(dx, dy) < 0.01) break;
    double error = std::atan2(dy, dx) - pose.theta;
    error = std::atan2(std::sin(error), std::cos(error));
    geometry_msgs::Twist t;
    t.angular.z = 4.0 * error;
    if (std::fabs(error) < 0.2) t.linear.x = std::min(1.0, 2.0 * std::hypot(dx, dy));
    cmd.publish(t);
    rate.sleep();
  }
  cmd.publish(geometry_msgs::Twist());
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "k_drawer");
  ros::NodeHandle n;
  ros::Publisher cmd = n.advertise<geometry_msgs::Twist>("turtle1/cmd_vel", 10);
  ros::Subscriber p = n.subscribe("turtle1/pose", 10, onPose);
  ros::Subscriber c = n.subscribe("chatter", 10, onChatter);
  ros::Rate rate(30);
  while (ros::ok()) {
    ros::spinOnce();
    if (go && have_pose) {
      double x = pose.x, y = pose.y;
      std::vector<std::pair<double, double>> corners = {
          {x, y + 2.0}, {x, y + 1.0}, {x + 1.2, y + 2.0}, {x, y + 1.0}, {x + 1.2, y}};
      for (auto& corner : corners) goTo(cmd, corner.first, corner.second);
      go = false;
    }
    rate.sleep();
  }
}
